"""MkDocs hook: the home page is the README, its links rewritten for the site."""

from __future__ import annotations

import re
from pathlib import Path

README = Path(__file__).resolve().parents[1] / "README.md"
#: A link to a repository file outside docs/: shown as its text (the site has no such page).
OUTSIDE = re.compile(r"\[([^\]]+)\]\((?!https?:|docs/)([^)]+)\)")


def on_page_read_source(page, config):  # noqa: ARG001 - MkDocs hook signature
    """The source of ``index.md`` is the README (``docs/`` prefixes dropped)."""
    if page.file.src_uri != "index.md":
        return None
    text = README.read_text(encoding="utf-8")
    text = re.sub(r"(\]\(|\()docs/", r"\1", text)
    return OUTSIDE.sub(r"\1", text)
