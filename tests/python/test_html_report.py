"""`tubemesh mesh --html` opened in headless Chromium: no console error, and the 3D view and
every histogram drawn (counted from a screenshot)."""
import json
import subprocess

import pytest
from PIL import Image

from chromium_page import Page

KIND_COLOURS = {"tet": (0x5b, 0x9b, 0xd5), "pyramid": (0xed, 0x7d, 0x31), "hex": (0x70, 0xad, 0x47)}


def pixels(image, rect, keep):
    box = (round(rect["x"]) + 1, round(rect["y"]) + 1, round(rect["x"] + rect["width"]) - 1,
           round(rect["y"] + rect["height"]) - 1)
    region = image.crop(box)
    return sum(1 for p in region.getdata() if keep(p)), region.width * region.height


def near(colour, tolerance=12):
    return lambda p: all(abs(a - b) <= tolerance for a, b in zip(p, colour))


@pytest.fixture(scope="module")
def opened(cli, tmp_path_factory):
    folder = tmp_path_factory.mktemp("html")
    report = folder / "report.html"
    subprocess.run([cli, "mesh", "--quiet", "-o", str(folder / "dam.msh"), "--html", str(report), "--report",
                    str(folder / "dam.json")], check=True)
    with Page(1400, 3600) as page:
        page.open(report)
        rects = page.evaluate("""JSON.stringify({
            view: document.getElementById('view').getBoundingClientRect(),
            phases: document.getElementById('phases').getBoundingClientRect(),
            histograms: Array.from(document.querySelectorAll('canvas.histogram'),
                                   c => c.getBoundingClientRect())})""")
        paper = page.evaluate("""JSON.stringify({
            shown: !document.getElementById('paper-section').hidden,
            title: document.getElementById('paper-title').textContent,
            rows: Array.from(document.getElementById('paper-table').rows,
                             r => Array.from(r.cells, c => c.textContent))})""")
        kinds = page.evaluate("JSON.stringify(JSON.parse(document.getElementById('tubemesh-data').textContent)"
                              ".histograms.map(h => h.kind))")
        page.screenshot(folder / "report.png")
        errors = page.errors()
    return {"report": report, "json": json.loads((folder / "dam.json").read_text()), "errors": errors, "rects": json.loads(rects), "kinds": json.loads(kinds),
            "paper": json.loads(paper),
            "image": Image.open(folder / "report.png").convert("RGB")}


def test_no_console_error(opened):
    assert opened["errors"] == []


def page_data(path):
    text = path.read_text()
    start = text.index('<script type="application/json" id="tubemesh-data">')
    return json.loads(text[text.index(">", start) + 1:text.index("</script>", start)])


def test_self_contained_and_small(opened):
    text = opened["report"].read_text()
    assert "<script src" not in text and "<link" not in text
    assert len(text.encode()) < 1_500_000


def test_the_page_holds_the_run_and_a_small_cut(opened):
    data = page_data(opened["report"])
    theirs = dict(opened["json"], outputs=[])
    assert data["report"] == theirs
    cells = data["view"]["cells"]
    assert 0 < len(cells["kind"]) <= 3000
    assert set(cells["kind"]) == {0, 1, 2}
    assert len(data["view"]["points"]) % 3 == 0
    assert [row[2] for row in data["table"] if row[1] == "Num. element"] == [
        str(theirs["tets"]), str(theirs["pyramids"]), str(theirs["hexes"])]


def test_every_kind_of_the_cut_has_its_faces(opened):
    # Each kind's surface is drawn: the pyramids between the ring and the tets too, and every
    # worst cell has faces for its marker.
    view = page_data(opened["report"])["view"]
    kinds = view["cells"]["kind"]
    faces_of = [0] * len(kinds)
    faces = view["faces"]
    i = 0
    while i < len(faces):
        faces_of[faces[i]] += 1
        i += 2 + faces[i + 1]
    for kind in (0, 1, 2):
        assert sum(n for n, k in zip(faces_of, kinds) if k == kind) > 0, kind
    pyramids = [c for c, k in enumerate(kinds) if k == 1]
    assert pyramids and all(faces_of[c] > 0 for c in pyramids)  # each shows at least its base
    assert all(faces_of[c] > 0 for c in view["worst"])
    assert any(kinds[c] == 1 for c in view["worst"])


def test_the_papers_column_is_beside_ours(opened):
    # The built-in dam block is the paper's first example: its Table 1 column beside the mesh's.
    paper = opened["paper"]
    assert paper["shown"]
    assert "Example 1 (paper-ex1)" in paper["title"]
    rows = {row[0]: row[1:] for row in paper["rows"][1:]}
    report = opened["json"]
    assert rows["Elements"] == ["58594", str(report["hexes"] + report["pyramids"] + report["tets"])]
    assert rows["Tet collapse min"] == ["0.362795", "%.6f" % report["quality"]["tet_collapse"]["min"]]
    assert rows["All-tet mesher's tets"] == ["1061195", "-"]


def test_the_3d_view_is_drawn(opened):
    drawn, total = pixels(opened["image"], opened["rects"]["view"], lambda p: p != (255, 255, 255))
    assert drawn > 0.2 * total
    for kind in ("tet", "pyramid", "hex"):  # every kind is in the cut, in its colour
        lit, _ = pixels(opened["image"], opened["rects"]["view"], near(KIND_COLOURS[kind], 60))
        assert lit > 100, kind


def test_every_histogram_is_drawn(opened):
    assert set(opened["kinds"]) == {"tet", "pyramid", "hex"}
    assert len(opened["rects"]["histograms"]) == len(opened["kinds"])
    for rect, kind in zip(opened["rects"]["histograms"], opened["kinds"]):
        bars, _ = pixels(opened["image"], rect, near(KIND_COLOURS[kind]))
        assert bars > 200, kind


def test_the_phase_bars_are_drawn(opened):
    bars, _ = pixels(opened["image"], opened["rects"]["phases"], near(KIND_COLOURS["tet"]))
    assert bars > 200
