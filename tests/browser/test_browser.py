"""The HTML reports in a real browser and their PDFs on paper (README "PDF reports").

The built CLI (FREESTAND_EXE) writes, into a temporary folder, the assess report of a shipped
case and a small fragility report, both with --pdf. Headless Chromium (Debian chromium and
chromium-driver through python3-selenium) loads each report.html from file:// and must see: no
request for anything but that file (and data:/about: URLs), no console message of level
SEVERE, and every <figure>'s SVG or image with a nonzero size and a screenshot that is not one
colour. Each report.pdf is rasterised with pdftoppm (poppler-utils): at least two pages, none
blank, "page N of M" on every page, and a table that runs over a page break has its header row
again on the next page. A missing browser, driver or converter fails these tests; it does not
skip them (scripts/setup.sh installs them all).
"""
import io
import json
import os
import pathlib
import shutil
import subprocess
import tempfile

import pytest
from PIL import Image
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXE = os.environ.get("FREESTAND_EXE", str(ROOT / "build" / "default" / "freestand"))
# A process that outlives this is a hung browser or converter: fail, do not wait.
TIMEOUT_S = 120
# A rendering is "not blank" when at least this share of its pixels differs from its most
# common colour (a figure's axes, lines and labels cover far more).
MIN_INK_SHARE = 0.002
WINDOW = (1280, 1024)


def program(name):
    path = shutil.which(name)
    assert path, f"{name} is not on PATH: scripts/setup.sh installs it"
    return path


def ink_share(image):
    """Share of the pixels that differ from the image's most common colour."""
    rgb = image.convert("RGB")
    colours = rgb.getcolors(maxcolors=rgb.width * rgb.height)
    most = max(count for count, _ in colours)
    return 1.0 - most / (rgb.width * rgb.height)


def is_blank(image):
    return ink_share(image) < MIN_INK_SHARE


def run(args, cwd=ROOT):
    r = subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=TIMEOUT_S)
    assert r.returncode == 0, f"{args} exited {r.returncode}:\n{r.stderr}"
    return r.stdout


@pytest.fixture(scope="module")
def reports():
    """The two report folders, written once for the module."""
    with tempfile.TemporaryDirectory(prefix="freestand_browser_") as tmp:
        tmp = pathlib.Path(tmp)
        run([EXE, "assess", "cases/glovebox-single.toml", "--pga", "0.3", "--pdf", "--out",
             str(tmp / "assess")])
        run([EXE, "fragility", "cases/block-ts1.toml", "--pga", "0.2:0.6:0.2", "--samples", "8",
             "--pool", "2", "--threads", "1", "--pdf", "--out", str(tmp / "fragility")])
        yield {"assess": tmp / "assess", "fragility": tmp / "fragility"}


@pytest.fixture(scope="module")
def browser():
    options = webdriver.ChromeOptions()
    options.binary_location = program("chromium")
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--no-first-run", "--disable-background-networking", "--disable-component-update",
                 "--disable-default-apps", "--disable-sync", "--disable-extensions",
                 f"--window-size={WINDOW[0]},{WINDOW[1]}", "--hide-scrollbars"):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    driver = webdriver.Chrome(service=Service(executable_path=program("chromedriver")), options=options)
    driver.set_page_load_timeout(TIMEOUT_S)
    try:
        yield driver
    finally:
        driver.quit()


def load(driver, html):
    """Loads html from file:// and returns (requested URLs, console entries)."""
    driver.get_log("performance")  # drop what an earlier page left
    driver.get_log("browser")
    driver.get(html.as_uri())
    assert driver.execute_script("return document.readyState") == "complete"
    urls = []
    for entry in driver.get_log("performance"):
        message = json.loads(entry["message"])["message"]
        if message["method"] == "Network.requestWillBeSent":
            urls.append(message["params"]["request"]["url"])
    return urls, driver.get_log("browser")


def test_the_blank_detector_flags_blank_and_passes_drawn_images():
    white = Image.new("RGB", (300, 200), "white")
    assert is_blank(white)
    assert is_blank(Image.new("RGB", (300, 200), (40, 90, 200)))
    assert is_blank(Image.new("RGBA", (300, 200), (0, 0, 0, 0)))
    drawn = white.copy()
    for x in range(20, 280):
        for y in (100, 101):
            drawn.putpixel((x, y), (0, 0, 0))
    assert not is_blank(drawn)


def test_the_page_checks_see_foreign_requests_and_console_errors(browser, tmp_path):
    page = tmp_path / "bad.html"
    page.write_text("<!DOCTYPE html><html><body><img src='http://localhost:9/x.png'>"
                    "<script>console.error('boom')</script></body></html>")
    urls, console = load(browser, page)
    assert "http://localhost:9/x.png" in urls
    assert any(e["level"] == "SEVERE" and "boom" in e["message"] for e in console)


@pytest.mark.parametrize("name, min_figures", [("assess", 8), ("fragility", 1)])
def test_report_html_renders_offline_without_errors(reports, browser, name, min_figures):
    html = reports[name] / "report.html"
    urls, console = load(browser, html)
    assert urls, "the performance log recorded no request at all: the check would be blind"
    foreign = [u for u in urls if u != html.as_uri() and not u.startswith(("data:", "about:"))]
    assert not foreign, f"report.html requested more than itself: {foreign}"
    severe = [e for e in console if e["level"] == "SEVERE"]
    assert not severe, f"console errors: {severe}"

    figures = browser.find_elements(By.CSS_SELECTOR, "figure")
    assert len(figures) >= min_figures
    for i, figure in enumerate(figures):
        drawings = figure.find_elements(By.CSS_SELECTOR, "svg, img")
        assert drawings, f"figure {i} has no svg or img"
        drawing = drawings[0]
        size = drawing.size
        assert size["width"] > 50 and size["height"] > 50, f"figure {i} is {size}"
        shot = Image.open(io.BytesIO(drawing.screenshot_as_png))
        assert shot.width > 50 and shot.height > 50
        assert not is_blank(shot), f"figure {i} renders as one colour (ink {ink_share(shot):.4f})"

    page = Image.open(io.BytesIO(browser.get_screenshot_as_png()))
    assert page.width >= WINDOW[0] * 0.9 and page.height >= WINDOW[1] * 0.5, page.size
    assert not is_blank(page)


def pdf_pages(pdf, tmp_path):
    info = run(["pdfinfo", str(pdf)])
    pages = int(next(line.split()[1] for line in info.splitlines() if line.startswith("Pages:")))
    run(["pdftoppm", "-r", "40", "-png", str(pdf), str(tmp_path / "page")])
    images = sorted(tmp_path.glob("page-*.png"))
    assert len(images) == pages
    texts = [run(["pdftotext", "-f", str(i), "-l", str(i), "-layout", str(pdf), "-"])
             for i in range(1, pages + 1)]
    return images, texts


def squash(text):
    return " ".join(text.split())


@pytest.mark.parametrize("name", ["assess", "fragility"])
def test_report_pdf_pages_are_numbered_and_not_blank(reports, tmp_path, name):
    program("pdftoppm")
    pdf = reports[name] / "report.pdf"
    assert pdf.read_bytes().startswith(b"%PDF-")
    images, texts = pdf_pages(pdf, tmp_path)
    assert len(images) >= 2
    for i, (png, text) in enumerate(zip(images, texts), start=1):
        with Image.open(png) as page:
            # The page body without the bottom margin, where the page number is.
            body = page.crop((0, 0, page.width, int(page.height * 0.9)))
            assert not is_blank(body), f"page {i} of {pdf} is blank (ink {ink_share(body):.4f})"
        assert f"page {i} of {len(images)}" in squash(text), f"page {i}: no page number"


def test_assess_pdf_repeats_table_headers_across_pages(reports, tmp_path):
    """The glove box's inputs table runs from page 1 onto page 2: the second page starts its
    part with the header row again."""
    _, texts = pdf_pages(reports["assess"] / "report.pdf", tmp_path)
    header = "quantity value unit source / note"
    pages = [i for i, t in enumerate(texts, start=1) if header in squash(t)]
    assert pages == [1, 2], f"header '{header}' on pages {pages}"
    # One table continued, not two tables: its first row on page 1, later rows on page 2.
    assert "mass" in squash(texts[0]) and "histories per level" in squash(texts[1])
