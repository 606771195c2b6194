"""`tubemesh batch --status OUTDIR --html FILE` opened in headless Chromium: no console error,
the three charts drawn (counted from a screenshot), a table row per block linking each
block's own report, which the batch wrote with the "html" format."""
import json
import pathlib
import subprocess

import pytest
from PIL import Image

from chromium_page import Page
from test_html_report import KIND_COLOURS, near, page_data, pixels

SMALL_DAM = ["--width", "3:3.5", "--depth", "3:3.5", "--lift-height", "1:1.2", "--diameter", "0.08:0.1",
             "--spacing", "0.9:1.1"]


@pytest.fixture(scope="module")
def opened(cli, tmp_path_factory):
    folder = tmp_path_factory.mktemp("batch")
    subprocess.run([cli, "make-dam", "--columns", "2", "--lifts", "2", "--seed", "7", *SMALL_DAM, "-o",
                    str(folder / "dam")], check=True, stdout=subprocess.DEVNULL)
    subprocess.run([cli, "batch", str(folder / "dam" / "manifest.json"), "-o", str(folder / "out"), "--formats",
                    "msh,html", "--quiet"], check=True)
    page_path = folder / "out" / "batch.html"
    subprocess.run([cli, "batch", "--status", str(folder / "out"), "--html", str(page_path)], check=True,
                   stdout=subprocess.DEVNULL)
    with Page(1500, 1600) as page:
        page.open(page_path)
        rects = page.evaluate("""JSON.stringify({
            elements: document.getElementById('elements').getBoundingClientRect(),
            quality: document.getElementById('quality').getBoundingClientRect(),
            seconds: document.getElementById('seconds').getBoundingClientRect(),
            rows: document.querySelectorAll('#blocks tr.block').length,
            links: Array.from(document.querySelectorAll('#blocks a'), a => a.getAttribute('href'))})""")
        page.screenshot(folder / "batch.png")
        errors = page.errors()
    return {"page": page_path, "errors": errors, "rects": json.loads(rects),
            "image": Image.open(folder / "batch.png").convert("RGB")}


def test_no_console_error(opened):
    assert opened["errors"] == []


def test_a_row_and_a_report_per_block(opened):
    blocks = page_data(opened["page"])["blocks"]
    assert len(blocks) == 4 and all(b["status"] == "done" for b in blocks)
    assert opened["rects"]["rows"] == 4
    assert sorted(opened["rects"]["links"]) == sorted(b["id"] + ".html" for b in blocks)
    for link in opened["rects"]["links"]:
        assert (opened["page"].parent / link).stat().st_size > 100_000  # the block's own page
    assert sum(b["elements"] for b in blocks) == sum(b["tets"] + b["pyramids"] + b["hexes"] for b in blocks)


def test_the_charts_are_drawn(opened):
    tets, _ = pixels(opened["image"], opened["rects"]["elements"], near(KIND_COLOURS["tet"]))
    assert tets > 2000
    minima, _ = pixels(opened["image"], opened["rects"]["quality"], near((0xc0, 0x50, 0x4d)))
    assert minima > 500
    seconds, _ = pixels(opened["image"], opened["rects"]["seconds"], near((0x7f, 0x7f, 0x7f)))
    assert seconds > 500
