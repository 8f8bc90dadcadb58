"""A self-contained HTML report: text, one table and figures (PNGs embedded, and linked)."""

from __future__ import annotations

import base64
import html
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

STYLE = """
body { font-family: system-ui, sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em;
       color: #222; line-height: 1.45; }
h1 { font-size: 1.6em; } h2 { font-size: 1.25em; margin-top: 1.6em; border-bottom: 1px solid #ddd; }
table { border-collapse: collapse; font-size: 0.92em; margin: 1em 0; }
th, td { border: 1px solid #ccc; padding: 0.3em 0.7em; text-align: right; }
th { background: #f3f3f3; } td:nth-child(2) { text-align: center; }
figure { margin: 1.5em 0; } figure img { max-width: 100%; border: 1px solid #eee; }
figcaption { font-size: 0.92em; color: #444; }
code { background: #f5f5f5; padding: 0 0.2em; }
"""


@dataclass(frozen=True)
class Figure:
    """A PNG beside the report, with its caption."""

    file: str
    caption: str


@dataclass(frozen=True)
class Section:
    """A further part of the page: a heading, paragraphs, a table and figures (each may be empty).

    Attributes
    ----------
    title : str
        The heading.
    paragraphs : sequence of str
        Plain text (escaped), above the table.
    header, rows : sequences of str
        The table, already formatted; no table when ``header`` is empty.
    figures : sequence of Figure
        PNGs below the table.
    left_columns : sequence of int
        Table columns of text, aligned left (0-based).
    nowrap : bool
        Keep every cell of the table on one line.
    """

    title: str
    paragraphs: Sequence[str] = ()
    header: Sequence[str] = ()
    rows: Sequence[Sequence[str]] = ()
    figures: Sequence[Figure] = ()
    left_columns: Sequence[int] = ()
    nowrap: bool = False


def _figure_html(folder: Path, figure: Figure) -> str:
    data = base64.b64encode((folder / figure.file).read_bytes()).decode("ascii")
    caption = html.escape(figure.caption)
    link = html.escape(figure.file)
    return (f'<figure id="{link}"><img src="data:image/png;base64,{data}" alt="{caption}">'
            f'<figcaption>{caption} (<a href="{link}">{link}</a>)</figcaption></figure>')


def table_html(header: Sequence[str], rows: Sequence[Sequence[str]], left_columns: Sequence[int] = (),
               nowrap: bool = False) -> str:
    """An HTML table of strings, escaped; the cells of ``left_columns`` (0-based) aligned left
    (text), the others right (numbers); ``nowrap`` keeps every cell on one line."""
    head = "".join(f"<th>{html.escape(cell)}</th>" for cell in header)
    left = ' style="text-align: left"'
    body = "\n".join("<tr>" + "".join(f"<td{left if k in left_columns else ''}>{html.escape(cell)}</td>"
                                       for k, cell in enumerate(row)) + "</tr>" for row in rows)
    style = ' style="white-space: nowrap"' if nowrap else ""
    return (f'<table class="results"{style}>\n<thead><tr>{head}</tr></thead>\n<tbody>\n{body}\n</tbody>\n'
            "</table>")


def write_html_report(path: Path, title: str, intro: Sequence[str], table_title: str, header: Sequence[str],
                      rows: Sequence[Sequence[str]], figures: Sequence[Figure],
                      files: Sequence[tuple[str, str]] = (), sections: Sequence[Section] = ()) -> Path:
    """Write one HTML page: the introduction, the table, the figures, then further sections.

    Parameters
    ----------
    path : Path
        The ``.html`` file; the figures' PNGs must be in the same folder.
    title : str
        Page title and heading.
    intro : sequence of str
        Paragraphs of plain text (escaped).
    table_title : str
        Heading above the table.
    header, rows : sequences of str
        The table's header and rows, already formatted.
    figures : sequence of Figure
        PNGs embedded in the page (so it stands alone) and linked to their files.
    files : sequence of (str, str)
        Other files of the folder to list with a description.
    sections : sequence of Section
        Parts after the figures, each with its heading, text, table and figures.

    Returns
    -------
    Path
        ``path``.
    """
    folder = path.parent
    parts = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
             f"<title>{html.escape(title)}</title><style>{STYLE}</style></head><body>",
             f"<h1>{html.escape(title)}</h1>"]
    parts += [f"<p>{html.escape(paragraph)}</p>" for paragraph in intro]
    parts += [f"<h2>{html.escape(table_title)}</h2>", table_html(header, rows), "<h2>Figures</h2>"]
    parts += [_figure_html(folder, figure) for figure in figures]
    for section in sections:
        parts.append(f"<h2>{html.escape(section.title)}</h2>")
        parts += [f"<p>{html.escape(paragraph)}</p>" for paragraph in section.paragraphs]
        if section.header:
            parts.append(table_html(section.header, section.rows, section.left_columns, section.nowrap))
        parts += [_figure_html(folder, figure) for figure in section.figures]
    if files:
        parts.append("<h2>Files</h2><ul>")
        parts += [f'<li><a href="{html.escape(name)}">{html.escape(name)}</a>: {html.escape(text)}</li>'
                  for name, text in files]
        parts.append("</ul>")
    parts.append("</body></html>")
    path.write_text("\n".join(parts), encoding="utf-8")
    return path
