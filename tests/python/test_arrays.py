"""The Mesh's arrays against the written files read back by meshio, and the views' ownership."""
import gc
import json
import subprocess

import meshio
import numpy as np

import tubemesh

MESHIO_TYPES = {"tets": "tetra", "pyramids": "pyramid", "hexes": "hexahedron", "triangles": "triangle",
                "quads": "quad"}


def by_type(mesh):
    blocks = {}
    for block in mesh.cells:
        blocks.setdefault(block.type, []).append(block.data)
    return {t: np.concatenate(d) for t, d in blocks.items()}


def test_arrays_match_the_msh_read_by_meshio(crankshaft, tmp_path):
    r = crankshaft
    path = tmp_path / "crankshaft.msh"
    r.write(path)
    m = meshio.read(path)
    assert np.array_equal(m.points, r.nodes)
    assert np.array_equal(r.nodes, np.column_stack([r.x, r.y, r.z]))
    cells = by_type(m)
    for name, meshio_type in MESHIO_TYPES.items():
        ours = getattr(r, name)
        assert ours.shape[0] > 0, name
        assert np.array_equal(cells[meshio_type], ours), name
    assert r.tets.shape[1] == 4 and r.pyramids.shape[1] == 5 and r.hexes.shape[1] == 8
    assert r.tets.max() < len(r.nodes) and r.tets.min() >= 0


def test_groups_match_the_msh_physical_groups(crankshaft, tmp_path):
    r = crankshaft
    path = tmp_path / "crankshaft.msh"
    r.write(path)
    m = meshio.read(path)
    tag_of = {name: int(tag_dim[0]) for name, tag_dim in m.field_data.items()}
    assert set(tag_of) == set(r.groups)
    for name, members in r.groups.items():
        for array, indices in members.items():
            physical = np.concatenate([tags for block, tags in zip(m.cells, m.cell_data["gmsh:physical"])
                                       if block.type == MESHIO_TYPES[array]])
            dim = 3 if array in ("tets", "pyramids", "hexes") else 2
            assert tag_of[name] and m.field_data[name][1] == dim
            assert np.array_equal(np.flatnonzero(physical == tag_of[name]), indices), (name, array)


def test_views_share_the_store_and_keep_it_alive():
    r = tubemesh.mesh("paper-ex3", size=40)
    tets, x = r.tets, r.x
    assert np.shares_memory(tets, r.tets) and np.shares_memory(x, r.x)
    assert not tets.flags.writeable and not x.flags.writeable
    first = tets.copy()
    del r
    gc.collect()
    assert np.array_equal(tets, first)  # the result lives on as the arrays' base
    assert tets.base is not None


def test_quality_per_kind_matches_the_report(crankshaft):
    """Every measure of the report's quality, per cell: kind "tet", key "collapse" is "tet_collapse"."""
    report = crankshaft.report["quality"]
    counts = {"tet": len(crankshaft.tets), "pyramid": len(crankshaft.pyramids), "hex": len(crankshaft.hexes)}
    seen = set()
    for kind, measures in crankshaft.quality.items():
        for measure, values in measures.items():
            summary = report[f"{kind}_{measure}"]
            seen.add(f"{kind}_{measure}")
            assert len(values) == summary["count"] == counts[kind]
            assert np.isclose(values.min(), summary["min"]) and np.isclose(values.max(), summary["max"])
            assert np.isclose(values.mean(), summary["mean"])
    assert seen == set(report)


def test_every_format_is_written_and_reads_back(crankshaft, tmp_path):
    counts = {"tetra": len(crankshaft.tets), "pyramid": len(crankshaft.pyramids), "hexahedron": len(crankshaft.hexes)}
    for ext in ("msh", "vtu"):
        path = tmp_path / f"m.{ext}"
        crankshaft.write(str(path))
        cells = by_type(meshio.read(path))
        assert {t: len(cells[t]) for t in counts} == counts, ext
    crankshaft.write(tmp_path / "m.vtm")
    assert (tmp_path / "m.vtm").exists() and (tmp_path / "m").is_dir()
    crankshaft.write(tmp_path / "m.inp")
    text = (tmp_path / "m.inp").read_text()
    assert "C3D4" in text and "C3D8" in text and "C3D5" not in text  # pyramids as collapsed bricks
    crankshaft.write(tmp_path / "c3d5.inp", inp_pyramid="c3d5")
    assert "C3D5" in (tmp_path / "c3d5.inp").read_text()
    crankshaft.write(tmp_path / "heat.inp", inp_family="heat")
    assert "DC3D4" in (tmp_path / "heat.inp").read_text()
    crankshaft.write(tmp_path / "water.inp", pipe_network=True, film_coefficient=800.0, reverse_flow=[1])
    assert "TYPE=D, ELSET=pipe_1_water" in (tmp_path / "water.inp").read_text()
    assert ", 800\n" in (tmp_path / "water.films.inp").read_text()
    crankshaft.write(tmp_path / "a.msh", msh_ascii=True)
    assert (tmp_path / "a.msh").read_text().startswith("$MeshFormat\n4.1 0")
    crankshaft.write_report(tmp_path / "r.json")
    assert json.loads((tmp_path / "r.json").read_text())["tets"] == len(crankshaft.tets)


def test_defaults_are_the_clis(cli, tmp_path):
    """No options: the CLI's built-in dam block with its defaults, the same mesh and report counts."""
    r = tubemesh.mesh()
    out, report = tmp_path / "dam.msh", tmp_path / "dam.json"
    subprocess.run([cli, "mesh", "--quiet", "-o", str(out), "--report", str(report)], check=True)
    theirs = json.loads(report.read_text())
    for key in ("nodes", "tets", "pyramids", "hexes", "boundary_triangles", "boundary_quads", "sizes", "quality"):
        assert r.report[key] == theirs[key], key
    m = meshio.read(out)
    assert np.array_equal(m.points, r.nodes)
    assert np.array_equal(by_type(m)["tetra"], r.tets)


def test_check_make_block_and_mesh_a_step_file(crankshaft, tmp_path):
    info = tubemesh.make_block(tmp_path / "b.step", preset="paper-ex3")
    assert info["pipe_count"] == 1 and (tmp_path / "b.step").exists()
    r = tubemesh.mesh(tmp_path / "b.step", size=40, threads=1)
    assert r.report["format"] == "STEP" and len(r.tets) > 0
    r.write(tmp_path / "b.msh")
    report = tubemesh.check(tmp_path / "b.msh")
    assert report["valid_and_conforming"]
    assert report["tets"] == len(r.tets) and report["hexes"] == len(r.hexes)
    assert "paper-ex1" in tubemesh.presets()


def test_moved_apexes_keep_the_rings_and_the_pyramid_bases():
    fixed = tubemesh.mesh("paper-ex3", threads=1)
    moved = tubemesh.mesh("paper-ex3", threads=1, move_apexes=True)
    assert np.array_equal(fixed.pyramids, moved.pyramids) and np.array_equal(fixed.hexes, moved.hexes)
    bases = np.unique(fixed.pyramids[:, :4])
    assert np.array_equal(fixed.nodes[bases], moved.nodes[bases])
    assert np.array_equal(fixed.nodes[np.unique(fixed.hexes)], moved.nodes[np.unique(fixed.hexes)])
    apexes = np.unique(fixed.pyramids[:, 4])
    assert np.any(fixed.nodes[apexes] != moved.nodes[apexes])
    tet = lambda r: r.report["quality"]["tet_collapse"]
    assert tet(moved)["min"] >= tet(fixed)["min"]
    assert moved.report["quality"]["pyramid_scaled_jacobian"]["min"] >= min(
        0.5, fixed.report["quality"]["pyramid_scaled_jacobian"]["min"]) - 1e-12


def test_slid_surface_nodes_keep_the_solid_and_its_rings():
    fixed = tubemesh.mesh("paper-ex3", threads=1, fixed_surface=True)
    slid = tubemesh.mesh("paper-ex3", threads=1)
    assert np.array_equal(fixed.hexes, slid.hexes) and np.array_equal(fixed.pyramids, slid.pyramids)
    held = np.unique(np.concatenate([fixed.hexes.ravel(), fixed.pyramids.ravel()]))
    assert np.array_equal(fixed.nodes[held], slid.nodes[held])
    surface = np.unique(fixed.triangles)
    assert np.any(fixed.nodes[surface] != slid.nodes[surface])
    volume = lambda r: r.report["check"]["volume"]
    assert abs(volume(slid) - volume(fixed)) <= 1e-9 * volume(fixed)
    assert slid.report["quality"]["tet_collapse"]["mean"] > fixed.report["quality"]["tet_collapse"]["mean"]


def test_economy_is_coarser_and_given_options_win():
    economy = tubemesh.mesh("paper-ex3", economy=True, threads=1)
    default = tubemesh.mesh("paper-ex3", threads=1)
    count = lambda r: len(r.hexes) + len(r.pyramids) + len(r.tets)
    assert count(economy) < count(default)
    # 4 nodes around and 2 layers: 8 hexes per station ring; 3 given layers: 12, the axial step
    # then follows the ring's own cap.
    assert len(economy.hexes) % 8 == 0
    layered = tubemesh.mesh("paper-ex3", economy=True, layers=3, threads=1)
    assert len(layered.hexes) % 12 == 0 and len(layered.hexes) != len(economy.hexes)


def test_local_ring_thins_the_ring_only_near_the_face(tmp_path):
    spec = tmp_path / "pipe.json"
    spec.write_text('{"box": [4, 3, 2], "check_clearance": false, "pipes": [{"path": "line", "diameter": 0.1, '
                    '"points": [[0, 1.5, 0.15], [4, 1.5, 0.15]]}]}')
    step = tmp_path / "pipe.step"
    tubemesh.make_block(step, spec=spec)
    local = tubemesh.mesh(step, threads=1, until="sweep")
    paper = tubemesh.mesh(step, threads=1, until="sweep", global_ring=True)
    assert local.report["sizes"]["St"] > paper.report["sizes"]["St"]
    assert any("thinned locally" in line for line in local.report["model"])
    assert not any("thinned locally" in line for line in paper.report["model"])
