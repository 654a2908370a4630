"""The documentation site covers the package: an API page per package, every theory page and
tutorial in the navigation (``make docs`` builds it with warnings as errors)."""

from __future__ import annotations

import json
import re

import pytest

from quick_cases import REPO

DOCS = REPO / "docs"
MKDOCS = (REPO / "mkdocs.yml").read_text(encoding="utf-8")
NAV = set(re.findall(r"^\s*-\s+(?:[^:\n]+:\s+)?(\S+\.(?:md|ipynb))\s*$", MKDOCS, re.M))
PACKAGES = sorted(
    p.name for p in (REPO / "src" / "ballscrew").iterdir() if (p / "__init__.py").is_file()
)


@pytest.mark.parametrize("package", PACKAGES)
def test_every_package_has_an_api_page_in_the_navigation(package):
    page = DOCS / "api" / f"{package}.md"
    assert page.is_file(), f"docs/api/{package}.md is missing"
    assert f"::: ballscrew.{package}" in page.read_text(encoding="utf-8")
    assert f"api/{package}.md" in NAV


def test_every_page_is_in_the_navigation_and_every_navigation_entry_exists():
    pages = {
        p.relative_to(DOCS).as_posix()
        for pattern in ("**/*.md", "**/*.ipynb")
        for p in DOCS.glob(pattern)
    }
    assert pages == NAV


@pytest.mark.parametrize("notebook", sorted((DOCS / "tutorials").glob("*.ipynb")), ids=str)
def test_tutorials_are_stored_without_outputs(notebook):
    """The site build executes them; stored outputs would go stale."""
    cells = json.loads(notebook.read_text(encoding="utf-8"))["cells"]
    assert all(not c.get("outputs") for c in cells if c["cell_type"] == "code")


@pytest.mark.parametrize("page", sorted(DOCS.rglob("*.md")), ids=lambda p: str(p.relative_to(DOCS)))
def test_pages_hold_no_control_characters(page):
    """A TeX command written through a Python string without ``r''`` loses its backslash to an
    escape (``\\tag`` → tab + ``ag``, ``\\beta`` → backspace + ``eta``)."""
    text = page.read_text(encoding="utf-8")
    found = sorted({repr(c) for c in re.findall(r"[\x00-\x08\x0b-\x1f\x7f\t]", text)})
    assert not found, f"{page.name}: {', '.join(found)}"
