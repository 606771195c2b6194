"""tubemesh.mesh's keywords come from the option table: its signature, its older spellings, and the
options the command line had alone (economy, assembly, the write options, the files)."""
import inspect
import json

import pytest
import tubemesh


def test_the_signature_lists_the_tables_options():
    params = inspect.signature(tubemesh.mesh).parameters
    for name in ("size", "circ", "economy", "assembly", "glue_tolerance", "fixed_surface", "global_ring",
                 "msh_ascii", "inp_family", "inp_pyramid", "pipe_network", "film_coefficient", "reverse_flow",
                 "output", "report", "html", "progress"):
        assert name in params, name
    assert params["layers"].default == 2 and params["size"].default is None
    assert "slide_surface" not in params and "local_ring" not in params
    assert "fixed_surface=False: Keep every surface node" in tubemesh.mesh.__doc__


def test_older_spellings_work_with_a_warning():
    with pytest.warns(FutureWarning, match='"slide_surface" is deprecated: use "fixed_surface"'):
        old = tubemesh.mesh("paper-ex3", threads=1, slide_surface=False)
    new = tubemesh.mesh("paper-ex3", threads=1, fixed_surface=True)
    assert (old.tets == new.tets).all() and (old.x == new.x).all()


def test_unknown_keywords_and_wrong_types_are_refused():
    with pytest.raises(tubemesh.Error, match='unknown option "sise"'):
        tubemesh.mesh("paper-ex3", sise=40)
    with pytest.raises(tubemesh.Error, match='^move_apexes must be true or false, got 1$'):
        tubemesh.mesh("paper-ex3", move_apexes=1)


def test_files_and_write_options_as_the_command_line(tmp_path):
    inp, report = tmp_path / "b.inp", tmp_path / "b.json"
    m = tubemesh.mesh("paper-ex3", size=40, threads=1, output=[inp], report=report, inp_family="heat")
    assert "DC3D4" in inp.read_text() and json.loads(report.read_text())["outputs"] == [str(inp)]
    m.write(tmp_path / "c.inp")  # mesh()'s write options by default
    assert "DC3D4" in (tmp_path / "c.inp").read_text()
    m.write(tmp_path / "d.inp", inp_family="stress")
    assert "DC3D4" not in (tmp_path / "d.inp").read_text()


def test_the_manifest_schema_and_the_signature_share_the_options(cli):
    import subprocess
    schema = json.loads(subprocess.run([cli, "batch", "--schema"], capture_output=True, text=True, check=True).stdout)
    assert schema["fixed_surface"]["deprecated_names"] == ["slide_surface"]
    assert schema["time_limit"]["default"] == 3600
    params = inspect.signature(tubemesh.mesh).parameters
    for key in set(schema) - {"formats", "time_limit"}:  # the batch's own: it names the files and kills workers
        assert key in params, key
        assert params[key].default == schema[key]["default"], key


def test_an_assembly_as_the_command_line(two_boxes):
    step = two_boxes(1)  # shares the face x = 1
    m = tubemesh.mesh(step, assembly=True, size=0.5, threads=1)
    assert len(m.report["assembly"]["solids"]) == 2
    with pytest.raises(tubemesh.Error, match="^assembly meshes every solid: leave solid out$"):
        tubemesh.mesh(step, assembly=True, solid=1)
