"""The little Markdown the reports use, as one self-contained HTML page.

Headings (``#`` to ``######``), pipe tables (the second row ``|---|``), images alone on a line
(embedded as base64 ``data:`` URLs when the file is found), bullet lists (``- ``), paragraphs,
and inline ``code``, ``**bold**`` and ``*emphasis*``. Everything else is text, escaped.

>>> print(to_html_body("# Table 4.3\\n\\n| HMM | ours |\\n|---|---|\\n| forward | **0.99** |\\n"), end="")
<h1 id="table-4-3">Table 4.3</h1>
<table>
<thead><tr><th>HMM</th><th>ours</th></tr></thead>
<tbody>
<tr><td>forward</td><td><strong>0.99</strong></td></tr>
</tbody>
</table>
"""

from __future__ import annotations

import base64
import html
import mimetypes
import os
import pathlib
import re

__all__ = ["to_html", "to_html_body"]

_HEADING = re.compile(r"^(#{1,6})\s+(.*)$")
_IMAGE = re.compile(r"^!\[([^\]]*)\]\(([^)\s]+)\)\s*$")
_STYLE = """
body { font-family: system-ui, sans-serif; max-width: 62rem; margin: 2rem auto; padding: 0 1rem;
       line-height: 1.45; color: #222; }
table { border-collapse: collapse; margin: 0.6rem 0 1rem; font-size: 0.92rem; }
th, td { border: 1px solid #ccc; padding: 0.2rem 0.55rem; text-align: right; }
th:first-child, td:first-child { text-align: left; }
thead { background: #f2f2f2; }
figure { margin: 0.6rem 0 1.2rem; }
img { max-width: 100%; }
code { background: #f4f4f4; padding: 0 0.2rem; }
h2 { border-bottom: 1px solid #ddd; padding-bottom: 0.2rem; margin-top: 2.2rem; }
"""


def to_html(markdown: str, *, title: str, images_from: str | os.PathLike[str] | None = None) -> str:
    """A whole HTML page; images are read from ``images_from`` (their paths are relative to it)
    and embedded, so the page stands alone."""
    body = to_html_body(markdown, images_from=images_from)
    return (f"<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            f"<title>{html.escape(title)}</title>\n<style>{_STYLE}</style>\n</head>\n<body>\n{body}</body>\n</html>\n")


def to_html_body(markdown: str, *, images_from: str | os.PathLike[str] | None = None) -> str:
    """The HTML of ``markdown``, block by block."""
    out: list[str] = []
    lines = markdown.splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        if not line.strip():
            i += 1
        elif heading := _HEADING.match(line):
            level, text = len(heading.group(1)), heading.group(2).strip()
            out.append(f"<h{level} id=\"{_anchor(text)}\">{_inline(text)}</h{level}>")
            i += 1
        elif image := _IMAGE.match(line):
            out.append(_figure(image.group(1), image.group(2), images_from))
            i += 1
        elif line.lstrip().startswith("|"):
            block = []
            while i < len(lines) and lines[i].lstrip().startswith("|"):
                block.append(lines[i])
                i += 1
            out.append(_table(block))
        elif line.startswith("- "):
            items = []
            while i < len(lines) and lines[i].startswith("- "):
                items.append(f"<li>{_inline(lines[i][2:])}</li>")
                i += 1
            out.append("<ul>\n" + "\n".join(items) + "\n</ul>")
        else:
            block = []
            while i < len(lines) and lines[i].strip() and not _starts_block(lines[i]):
                block.append(lines[i].strip())
                i += 1
            out.append(f"<p>{_inline(' '.join(block))}</p>")
    return "\n".join(out) + "\n"


def _starts_block(line: str) -> bool:
    return bool(_HEADING.match(line) or _IMAGE.match(line) or line.lstrip().startswith("|") or line.startswith("- "))


def _anchor(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-")


def _inline(text: str) -> str:
    parts = re.split(r"(`[^`]*`)", text)
    rendered = []
    for part in parts:
        if part.startswith("`") and part.endswith("`") and len(part) >= 2:
            rendered.append(f"<code>{html.escape(part[1:-1])}</code>")
            continue
        escaped = html.escape(part)
        escaped = re.sub(r"\*\*(.+?)\*\*", r"<strong>\1</strong>", escaped)
        escaped = re.sub(r"(?<![\w*])\*(?!\s)(.+?)(?<!\s)\*(?![\w*])", r"<em>\1</em>", escaped)
        rendered.append(escaped)
    return "".join(rendered)


def _cells(row: str) -> list[str]:
    row = row.strip()
    if row.startswith("|"):
        row = row[1:]
    if row.endswith("|"):
        row = row[:-1]
    return [cell.strip() for cell in row.split("|")]


def _table(rows: list[str]) -> str:
    has_header = len(rows) > 1 and all(set(c) <= set("-: ") and c for c in _cells(rows[1]))
    head, body = (rows[:1], rows[2:]) if has_header else ([], rows)
    out = ["<table>"]
    if head:
        out.append("<thead><tr>" + "".join(f"<th>{_inline(c)}</th>" for c in _cells(head[0])) + "</tr></thead>")
    out.append("<tbody>")
    out += ["<tr>" + "".join(f"<td>{_inline(c)}</td>" for c in _cells(r)) + "</tr>" for r in body]
    out.append("</tbody>\n</table>")
    return "\n".join(out)


def _figure(alt: str, src: str, images_from: str | os.PathLike[str] | None) -> str:
    if images_from is not None:
        path = pathlib.Path(images_from) / src
        if path.is_file():
            kind = mimetypes.guess_type(path.name)[0] or "application/octet-stream"
            src = f"data:{kind};base64,{base64.b64encode(path.read_bytes()).decode('ascii')}"
    return (f"<figure><img src=\"{html.escape(src, quote=True)}\" alt=\"{html.escape(alt, quote=True)}\">"
            f"<figcaption>{_inline(alt)}</figcaption></figure>")
