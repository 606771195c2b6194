"""Errors raise tubemesh.Error with the CLI's one-line message."""
import subprocess

import pytest

import tubemesh


def cli_message(cli, *args):
    done = subprocess.run([cli, *args], capture_output=True, text=True)
    assert done.returncode == 2
    line = done.stderr.strip()
    assert line.startswith("tubemesh: ") and "\n" not in line
    return line[len("tubemesh: "):]


def test_missing_file_has_the_clis_message(cli, tmp_path):
    missing = str(tmp_path / "missing.step")
    with pytest.raises(tubemesh.Error) as e:
        tubemesh.mesh(missing)
    assert str(e.value) == cli_message(cli, "mesh", missing, "-o", str(tmp_path / "x.msh"))
    assert isinstance(e.value, RuntimeError)


def test_several_solids_name_the_keyword_and_the_assembly(two_boxes):
    step = two_boxes(5)
    with pytest.raises(tubemesh.Error) as e:
        tubemesh.mesh(step)
    message = str(e.value)
    assert "holds 2 solids" in message
    assert "solid=N (N from 1 to 2)" in message and "--solid" not in message
    assert "assembly=True" in message and "--assembly" not in message


def test_bad_options_name_the_keyword():
    with pytest.raises(tubemesh.Error, match="^size must be a positive number, got -1$"):
        tubemesh.mesh("paper-ex3", size=-1)
    with pytest.raises(tubemesh.Error, match="^contradictory sizes: sweep_size 50 must be smaller than size 40$"):
        tubemesh.mesh("paper-ex3", size=40, sweep_size=50)
    with pytest.raises(tubemesh.Error, match="^circ must be between 4 and 4096, got 2$"):
        tubemesh.mesh("paper-ex3", circ=2)
    with pytest.raises(tubemesh.Error, match="^until nope: no such stage"):
        tubemesh.mesh("paper-ex3", until="nope")


def test_refused_sizes_have_the_clis_message(cli, tmp_path):
    with pytest.raises(tubemesh.Error) as e:
        tubemesh.mesh("paper-ex1", size=0.01)
    assert str(e.value) == cli_message(cli, "mesh", "--size", "0.01", "-o", str(tmp_path / "x.msh"))


def test_write_and_check_errors(crankshaft, tmp_path):
    with pytest.raises(tubemesh.Error, match="unknown mesh format"):
        crankshaft.write(tmp_path / "m.txt")
    with pytest.raises(tubemesh.Error, match="does not exist"):
        crankshaft.write(tmp_path / "no" / "m.msh")
    with pytest.raises(tubemesh.Error, match="must end in .html"):
        crankshaft.write_html(tmp_path / "r.htm")
    with pytest.raises(tubemesh.Error):
        tubemesh.check(tmp_path / "missing.msh")
    with pytest.raises(tubemesh.Error):
        tubemesh.make_block(tmp_path / "b.step")  # no preset, seed or spec
    with pytest.raises(tubemesh.Error, match="^inp_pyramid c3d5 has no heat-transfer or coupled variant"):
        crankshaft.write(tmp_path / "m.inp", inp_family="heat", inp_pyramid="c3d5")
    with pytest.raises(tubemesh.Error, match="^inp_family thermal: not one of stress, heat, coupled, coupled-abaqus$"):
        crankshaft.write(tmp_path / "m.inp", inp_family="thermal")
    partial = tubemesh.mesh("paper-ex3", size=40, until="pyramids")
    with pytest.raises(tubemesh.Error, match="Abaqus .inp needs every boundary face on a cell"):
        partial.write(tmp_path / "m.inp")
