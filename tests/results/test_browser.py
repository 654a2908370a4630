"""A report and the index page, opened in a real browser (headless Chromium via Playwright).

Checks what a user sees: no console error, every image decoded, the inputs table present.
Chromium is Debian's package (``/usr/bin/chromium``), installed by ``make`` or ``.ci/run``;
the test is skipped only where it cannot be installed (not root, no apt-get), never in CI.
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from ballscrew.results import write_results
from ballscrew.results.index import write_index
from quick_cases import EXAMPLES

CHROMIUM = Path("/usr/bin/chromium")
ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]


def _why_no_browser() -> str | None:
    """Why the browser test cannot run here (None: it can)."""
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:
        return "the playwright package is not installed (pip install -e '.[test]')"
    if CHROMIUM.is_file():
        return None
    if os.environ.get("CI"):
        return None  # CI must run it: fail below rather than skip
    if os.geteuid() != 0 or shutil.which("apt-get") is None:
        return f"{CHROMIUM} is missing and cannot be installed here (needs root and apt-get)"
    return f"{CHROMIUM} is missing: run `make test` or `apt-get install -y chromium`"


pytestmark = pytest.mark.skipif(_why_no_browser() is not None, reason=str(_why_no_browser()))


@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    from playwright.sync_api import sync_playwright

    profile = tmp_path_factory.mktemp("chromium-profile")
    with sync_playwright() as p:
        context = p.chromium.launch_persistent_context(
            str(profile), executable_path=str(CHROMIUM), args=ARGS, headless=True
        )
        yield context
        context.close()


@pytest.fixture(scope="module")
def results(tmp_path_factory) -> Path:
    """A design-check results folder (a second of work) and the index page over it."""
    import ballscrew

    root = tmp_path_factory.mktemp("browser")
    case_file = EXAMPLES / "gao2019_tcr.toml"
    result = ballscrew.design_check(ballscrew.load_case(case_file))
    write_results(result, root / "check", case_file)
    write_index(root, title="browser test")
    return root


def _open(context, path: Path, shot: Path) -> dict:
    """Open ``path``, collect console errors and failed requests, check every image."""
    page = context.new_page()
    errors: list[str] = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("requestfailed", lambda r: errors.append(f"failed to load {r.url}"))
    page.goto(path.as_uri(), wait_until="load")
    images = page.eval_on_selector_all(
        "img", "els => els.map(e => [e.getAttribute('alt'), e.complete, e.naturalWidth])"
    )
    headings = page.eval_on_selector_all("h2", "els => els.map(e => e.textContent)")
    tables = page.eval_on_selector_all(
        "table", "els => els.map(t => [...t.querySelectorAll('th')].map(h => h.textContent))"
    )
    page.screenshot(path=str(shot), full_page=True)
    page.close()
    return {"errors": errors, "images": images, "headings": headings, "tables": tables}


def test_the_report_renders_with_its_inputs_and_every_figure(browser, results, tmp_path):
    shot = tmp_path / "report.png"
    seen = _open(browser, results / "check" / "report.html", shot)
    assert seen["errors"] == []
    assert seen["images"], "the report shows no figure"
    broken = [alt for alt, complete, width in seen["images"] if not complete or width == 0]
    assert broken == [], f"images not loaded: {broken}"
    assert seen["headings"][:2] == ["Inputs", "Warnings"]
    assert seen["tables"][0][:3] == ["input", "value", "unit"]  # the inputs table comes first
    assert shot.stat().st_size > 10_000


def test_the_index_renders_and_links_the_report(browser, results, tmp_path):
    shot = tmp_path / "index.png"
    seen = _open(browser, results / "index.html", shot)
    assert seen["errors"] == []
    assert seen["images"], "the index shows no key figure"
    assert all(complete and width > 0 for _, complete, width in seen["images"])
    assert 'href="check/report.html"' in (results / "index.html").read_text(encoding="utf-8")
    assert shot.stat().st_size > 5_000
