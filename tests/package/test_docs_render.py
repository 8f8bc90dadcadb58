"""The documentation site as a reader sees it: maths rendered, figures present, no blank page.

The site is built once (``mkdocs build --strict``), then for every page of ``docs/``:

- the formulas are MathML (``docs/hooks/maths.py`` turns ``$...$`` and ``$$ ... $$`` into it at
  build time), on the pages that have formulas, and no ``$`` is left in the text a reader sees
  (code excepted);
- every ``<img>`` of the page points to a file of the built site that is a PNG that decodes;
  the figures of ``docs/img/`` (``bash scripts/docs-images.sh``) are small and each is shown;
- a headless Chromium screenshot of the page (1280 x 2000, as ``chromium --headless
  --screenshot``) is not blank: the article's area has contrast.

``PENDULUM_DOCS_SHOTS=DIR`` keeps the screenshots in DIR, to look at them.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

REPO = Path(__file__).resolve().parents[2]
DOCS = REPO / "docs"
PAGES = sorted(p.stem for p in DOCS.glob("*.md"))
# The pages whose formulas are LaTeX: each must come out as MathML (a page may gain formulas;
# these may not lose theirs).
MATH_PAGES = {"index", "math", "certificate", "importers", "derivatives", "split", "masters", "study"}
# The figures each page must show (docs/img/, drawn by scripts/docs-images.sh).
FIGURES = {
    "study": {"study_fig3_numeric.png", "study_fig4_exact.png", "study_fig5_overlay.png",
              "study_period_ratio.png", "study_speed_vs_error.png"},
    "index": {"study_fig5_overlay.png"},
    "math": {"study_period_ratio.png"},
    "certificate": {"judge_cs_rk4.png"},
    "importers": {"judge_me_euler.png"},
    "solvers": {"bench_wp_P1.png"},
    "masters": {"masters_wp.png"},
}
MAX_FIGURE_BYTES = 150_000
CHROMIUM_INSTALL = "apt-get install -y chromium (or sudo bash scripts/install-system-packages.sh)"
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


class PageText(HTMLParser):
    """The article of a built page: the text a reader sees outside code and formulas, the
    ``<math>`` elements, the ``<img>`` sources."""

    HIDDEN = {"code", "pre", "script", "style", "math", "kbd", "svg"}

    def __init__(self) -> None:
        super().__init__()
        self.hidden = 0
        self.in_article = 0
        self.text: list[str] = []
        self.maths = 0
        self.images: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        if tag == "article":
            self.in_article += 1
        if tag in self.HIDDEN:
            self.hidden += 1
        if tag == "math":
            self.maths += 1
        if tag == "img" and self.in_article:
            self.images.append(dict(attrs).get("src") or "")

    def handle_endtag(self, tag: str) -> None:
        if tag == "article":
            self.in_article -= 1
        if tag in self.HIDDEN:
            self.hidden -= 1

    def handle_data(self, data: str) -> None:
        if self.in_article and self.hidden == 0:
            self.text.append(data)


def chromium() -> str:
    """The Chromium program, or a skip that says how to install it."""
    for name in ("chromium", "chromium-browser", "google-chrome"):
        found = shutil.which(name)
        if found:
            return found
    pytest.skip(f"no chromium for the screenshots: {CHROMIUM_INSTALL}")


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The site, built once for this module in strict mode."""
    out = tmp_path_factory.mktemp("site")
    env = dict(os.environ, NO_MKDOCS_2_WARNING="1")
    built = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--quiet", "-d", str(out)],
                           cwd=REPO, env=env, capture_output=True, text=True, timeout=600, check=False)
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    return out


@pytest.fixture(scope="module")
def shots(tmp_path_factory: pytest.TempPathFactory) -> Path:
    kept = os.environ.get("PENDULUM_DOCS_SHOTS")
    if kept:
        Path(kept).mkdir(parents=True, exist_ok=True)
        return Path(kept)
    return tmp_path_factory.mktemp("shots")


def read_page(site: Path, page: str) -> PageText:
    html = site / f"{page}.html"
    assert html.is_file(), f"{page}.md built no {html.name}"
    parsed = PageText()
    parsed.feed(html.read_text(encoding="utf-8"))
    return parsed


@pytest.mark.parametrize("page", PAGES)
def test_page_maths_are_mathml_and_no_dollar_is_left(site: Path, page: str) -> None:
    parsed = read_page(site, page)
    text = "".join(parsed.text)
    assert "$" not in text, \
        f"{page}: a $ in the text a reader sees (an unrendered formula?): " \
        f"...{text[max(0, text.index('$') - 80):text.index('$') + 40]!r}..."
    if page in MATH_PAGES:
        assert parsed.maths > 0, f"{page}: its formulas are not MathML (docs/hooks/maths.py did not run?)"
    for ascii_formula in ("w0^2", "sqrt(g/L)", "sin^2(theta"):
        assert page not in MATH_PAGES or ascii_formula not in text, \
            f"{page}: the ASCII formula {ascii_formula!r} is left; write it in LaTeX ($...$)"


@pytest.mark.parametrize("page", PAGES)
def test_page_images_are_pngs_of_the_site(site: Path, page: str) -> None:
    parsed = read_page(site, page)
    shown = set()
    for source in parsed.images:
        assert not re.match(r"[a-z]+:", source), f"{page}: <img src={source!r}> is fetched from outside the site"
        target = (site / source).resolve()
        assert target.is_file(), f"{page}: <img src={source!r}> has no file in the built site"
        data = target.read_bytes()
        assert data.startswith(PNG_MAGIC), f"{page}: {source} is not a PNG"
        from PIL import Image  # pillow: the [animate] extra, in [test]
        with Image.open(target) as image:
            image.load()  # decodes the whole picture: a truncated file raises here
            assert image.width >= 400 and image.height >= 200, f"{page}: {source} is {image.size}, too small to read"
        shown.add(target.name)
    missing = FIGURES.get(page, set()) - shown
    assert not missing, f"{page}: does not show {sorted(missing)} (bash scripts/docs-images.sh draws them)"


def test_committed_figures_are_small_and_each_is_shown() -> None:
    figures = sorted((DOCS / "img").glob("*.png"))
    assert figures, "docs/img/ has no figure: bash scripts/docs-images.sh draws them"
    used = set().union(*FIGURES.values())
    for figure in figures:
        size = figure.stat().st_size
        assert size < MAX_FIGURE_BYTES, f"docs/img/{figure.name} is {size} bytes, over {MAX_FIGURE_BYTES}"
        assert figure.name in used, f"docs/img/{figure.name} is on no page (or missing from FIGURES here)"
    script = (REPO / "scripts" / "docs-images.sh").read_text(encoding="utf-8")
    for name in used:  # the study's figures keep the study's own names, with "study_" before them
        assert name.removesuffix(".png").removeprefix("study_") in script, \
            f"scripts/docs-images.sh does not draw {name}"


@pytest.mark.parametrize("page", PAGES)
def test_page_screenshot_is_not_blank(site: Path, shots: Path, page: str) -> None:
    program = chromium()
    shot = shots / f"{page}.png"
    shot.unlink(missing_ok=True)
    command = [program, "--headless", "--disable-gpu", "--hide-scrollbars", "--no-first-run",
               "--virtual-time-budget=5000", f"--screenshot={shot}", "--window-size=1280,2000",
               (site / f"{page}.html").as_uri()]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        command.insert(1, "--no-sandbox")  # Chromium refuses to run as root with its sandbox
    done = subprocess.run(command, capture_output=True, text=True, timeout=120, check=False)
    assert done.returncode == 0 and shot.is_file(), f"chromium made no screenshot of {page}: {done.stderr[-1500:]}"
    from PIL import Image, ImageStat
    with Image.open(shot) as image:
        assert image.size == (1280, 2000)
        # the article's column (left of it the navigation, right the table of contents)
        article = image.convert("L").crop((290, 90, 1000, 2000))
        spread = ImageStat.Stat(article).stddev[0]
        dark = sum(article.histogram()[:128]) / (article.width * article.height)
    assert spread > 15, f"{page}: the screenshot's article is blank (grey-level spread {spread:.1f}); {shot}"
    assert dark > 0.005, f"{page}: the screenshot's article has almost no text ({dark:.2%} dark pixels); {shot}"


def test_maths_hook_leaves_code_and_prices_alone() -> None:
    """The hook's rules on a sample: formulas become MathML, code and a lone $ stay as written."""
    import importlib.util

    import markdown

    spec = importlib.util.spec_from_file_location("maths_hook", DOCS / "hooks" / "maths.py")
    assert spec is not None and spec.loader is not None
    hook = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(hook)
    md = markdown.Markdown(extensions=[hook.MathExtension(), "fenced_code"])
    html = md.convert("Energy $H = \\omega^2/2$ and `echo $HOME` cost 5 $ each.\n\n"
                      "$$\nT = \\frac{4 K(m)}{w_0}\n$$\n\n```sh\n$$\nx=$PATH\n```\n")
    assert html.count("<math") == 2 and 'display="block"' in html
    assert "<code>echo $HOME</code>" in html and "cost 5 $ each" in html
    assert "$$\nx=$PATH" in html, "a fenced block's $$ was taken for a formula"
    with pytest.raises(ValueError, match="cannot render the formula"):
        markdown.Markdown(extensions=[hook.MathExtension()]).convert("$\\frac{1}{$ and $x$")
