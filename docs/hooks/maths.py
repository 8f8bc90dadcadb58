"""MkDocs hook: the pages' LaTeX maths, ``$...$`` inline and ``$$ ... $$`` displayed, as MathML.

The formulas are turned into MathML while the site is built (``latex2mathml``), so the pages
need no script and no network to show them: browsers render MathML natively (Chromium since
version 109, Firefox, Safari). ``tests/package/test_docs_render.py`` builds the site and checks that
every page with maths carries MathML and no ``$`` left over, in a headless Chromium.

- ``$$`` on a line of its own opens a displayed formula and the next line holding only ``$$``
  closes it (outside fenced code blocks); it becomes a ``<math display="block">`` element.
- ``$...$`` inside a paragraph is an inline formula: no blank after the opening ``$`` or
  before the closing one, and no letter or digit right after it (so "5 $ and 6 $" stays text).
  Code spans keep their ``$`` (the backtick pattern runs first), and ``\\$`` is a dollar sign.

A formula that ``latex2mathml`` cannot parse fails the build with its page and its text.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from typing import Any

from latex2mathml.converter import convert
from markdown import Extension, Markdown
from markdown.inlinepatterns import InlineProcessor
from markdown.preprocessors import Preprocessor

INLINE = r"(?<![\\$\w])\$(?![\s$])((?:[^$\\]|\\.)+?)(?<![\s\\])\$(?![\w$])"
FENCE = re.compile(r"^\s*(`{3,}|~{3,})")


def mathml(latex: str, display: bool) -> str:
    """The MathML of ``latex``; a formula latex2mathml cannot read raises ValueError naming it."""
    try:
        markup = convert(latex.strip(), display="block" if display else "inline")
        ET.fromstring(markup)  # well-formed, or the page would break around it
    except Exception as error:  # latex2mathml raises its own kinds, and IndexError on bad input
        raise ValueError(f"cannot render the formula {latex!r}: {error}") from error
    return markup


class DisplayMath(Preprocessor):
    """``$$`` lines around a formula -> a raw HTML block holding its MathML."""

    def run(self, lines: list[str]) -> list[str]:
        out: list[str] = []
        fence: str | None = None
        formula: list[str] | None = None
        indent = ""
        for line in lines:
            if formula is not None:
                if line.strip() == "$$":
                    html = f'<div class="math-display">{mathml(" ".join(formula), True)}</div>'
                    # indented as the opening $$, so that a formula stays inside its list item
                    out.extend(["", indent + self.md.htmlStash.store(html), ""])
                    formula = None
                else:
                    formula.append(line)
                continue
            opened = FENCE.match(line)
            if fence is None and opened:
                fence = opened.group(1)[0]
            elif fence is not None and opened and opened.group(1)[0] == fence:
                fence = None
            elif fence is None and line.strip() == "$$":
                formula = []
                indent = line[:len(line) - len(line.lstrip())]
                continue
            out.append(line)
        if formula is not None:
            raise ValueError(f"a $$ block is never closed: {' '.join(formula)[:80]!r}")
        return out


class InlineMath(InlineProcessor):
    """``$...$`` -> MathML, stashed so that the other inline patterns leave it alone."""

    def handleMatch(self, m: re.Match[str], data: str) -> tuple[str, int, int]:  # noqa: N802 (Markdown's name)
        return self.md.htmlStash.store(mathml(m.group(1), False)), m.start(0), m.end(0)


class MathExtension(Extension):
    """The two patterns: the block before the fenced code (priority 30 > 25), the inline one
    after code spans (190) and escapes (180) but before emphasis, so ``_`` and ``*`` in a formula
    stay LaTeX."""

    def extendMarkdown(self, md: Markdown) -> None:  # noqa: N802 (Markdown's name)
        md.preprocessors.register(DisplayMath(md), "pendulum_display_math", 30)
        md.inlinePatterns.register(InlineMath(INLINE, md), "pendulum_inline_math", 175)


def on_config(config: Any) -> Any:
    """Add the extension to the site's Markdown."""
    config.markdown_extensions.append(MathExtension())
    return config
