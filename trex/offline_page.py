"""What the offline pages of ``trex player`` and ``trex slides`` share: their look and how
their data is written into them.

A page is one HTML file with its CSS and JavaScript inline and its data in a
``<script type="application/json">`` block; it fetches nothing from anywhere but the files
beside it (pictures, clips), named relatively.
"""

from __future__ import annotations

import html
import json
from pathlib import Path

#: how both pages start, up to their own ``<style>`` (no icon is fetched: ``data:,``)
HEAD = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<link rel="icon" href="data:,">
<title>{{TITLE}}</title>"""

#: the CSS both pages start from (colours as the theme's: ink, idle grey, called blue)
BASE_CSS = """
  :root { color-scheme: dark; --ink: #e8ecf2; --idle: #8a93a3; --called: #4f8ff7; }
  body { margin: 0; background: #10141c; color: var(--ink);
         font-family: "DejaVu Sans", system-ui, sans-serif; }
  main { max-width: 980px; margin: 0 auto; padding: 16px; }
  h1 { font-size: 1.25rem; font-weight: normal; margin: 0 0 4px; }
  .sub { color: var(--idle); font-size: 0.85rem; margin: 0 0 12px; }
  .bar { display: flex; align-items: center; gap: 12px; margin: 12px 0 6px; }
  button { background: #1c2433; color: var(--ink); border: 1px solid #2a3a55;
           border-radius: 4px; padding: 4px 12px; font: inherit; cursor: pointer; }
  button:disabled { opacity: 0.4; cursor: default; }
  #counter { font-variant-numeric: tabular-nums; min-width: 8em; }
  #caption { font-size: 1.1rem; margin: 6px 0; }
  .keys { color: var(--idle); font-size: 0.8rem; margin-top: 14px; }
  kbd { border: 1px solid #2a3a55; border-radius: 3px; padding: 0 4px; }
"""


def embedded_json(data: object) -> str:
    """``data`` as JSON that can sit inside a ``<script>`` block (no ``</`` in it).

    >>> embedded_json({"caption": "</script>"})
    '{"caption": "<\\\\/script>"}'
    """
    return json.dumps(data, ensure_ascii=False).replace("</", "<\\/")


def fill(template: str, data: object, **fields: str | int) -> str:
    """The page: ``{{HEAD}}``, ``{{BASE_CSS}}``, ``{{DATA}}`` (``data``,
    :func:`embedded_json`) and each ``{{NAME}}`` of ``fields``, HTML-escaped, put into
    ``template``.

    >>> fill("<b>{{TITLE}}</b>{{DATA}}", [1], TITLE="a < b")
    '<b>a &lt; b</b>[1]'
    """
    page = template.replace("{{HEAD}}", HEAD).replace("{{BASE_CSS}}", BASE_CSS)
    for name, value in fields.items():
        page = page.replace("{{" + name + "}}", html.escape(str(value)))
    return page.replace("{{DATA}}", embedded_json(data))


def write_page(folder: Path, template: str, title: str, steps: list[dict],
               **fields: str | int) -> Path:
    """Write ``folder/index.html``: ``template`` filled (:func:`fill`) with the data
    ``{"title": title, "steps": steps}``, ``TITLE`` and ``fields``; returns its path."""
    page = fill(template, {"title": title, "steps": steps}, TITLE=title, **fields)
    path = folder / "index.html"
    path.write_text(page, encoding="utf-8")
    return path
