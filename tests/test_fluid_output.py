"""fluid.output: HDF5 series and snapshots round-trip, the XDMF companion points at
datasets that exist with the dimensions it states, and a run that raised leaves a
readable file."""

import xml.etree.ElementTree as ET

import h5py
import numpy as np
import pytest

from cosim.errors import InputError
from fluid.output import H5Output, read_series, read_snapshot


def _snapshot_fields(n, dim, rng):
    return dict(rho=1000 + rng.random(n), p=rng.random(n), vel=rng.random((n, dim)),
                kind=rng.integers(0, 4, n).astype(np.int8), ids=np.arange(n, dtype=np.int64))


def test_series_round_trip_across_buffer_boundaries(tmp_path):
    path = tmp_path / "run.h5"
    with H5Output(path, dim=2, attrs={"dx": 0.01, "case": "tank"}, buffer_rows=3) as out:
        for i in range(7):  # 7 rows: two full buffers and a partial one at close
            out.series("body", 0.1 * i, x=i, z=2.0 * i, f=[i, -i, 0.5])
        out.series_block("ledger/box", np.arange(4.0), force=np.ones((4, 3)), m=np.arange(4.0))
        out.series_block("ledger/box", [4.0], force=[[2.0, 2.0, 2.0]], m=[9.0])
    s = read_series(path, "body")
    np.testing.assert_array_equal(s["t"], 0.1 * np.arange(7))
    np.testing.assert_array_equal(s["x"], np.arange(7.0))
    np.testing.assert_array_equal(s["z"], 2.0 * np.arange(7))
    assert s["f"].shape == (7, 3) and s["f"][5].tolist() == [5.0, -5.0, 0.5]
    b = read_series(path, "ledger/box")
    assert b["force"].shape == (5, 3) and b["force"][4].tolist() == [2.0, 2.0, 2.0]
    np.testing.assert_array_equal(b["m"], [0.0, 1.0, 2.0, 3.0, 9.0])
    with h5py.File(path) as f:
        assert f.attrs["dx"] == 0.01 and f.attrs["case"] == "tank" and f.attrs["dim"] == 2


@pytest.mark.parametrize("dim", [2, 3])
def test_snapshots_round_trip_and_xdmf_points_at_real_datasets(tmp_path, dim):
    rng = np.random.default_rng(1)
    path = tmp_path / "run.h5"
    sizes, times = (50, 47, 52), (0.0, 0.25, 0.5)  # particles leave and come: N changes
    written = []
    with H5Output(path, dim=dim) as out:
        for t, n in zip(times, sizes):
            pos = rng.random((n, dim))
            fields = _snapshot_fields(n, dim, rng)
            assert out.snapshot(t, pos, **fields) == len(written)
            written.append((pos, fields))
    for k, (pos, fields) in enumerate(written):
        snap = read_snapshot(path, k)
        assert snap["t"] == times[k]
        np.testing.assert_array_equal(snap["pos"], pos)
        for name, a in fields.items():
            np.testing.assert_array_equal(snap[name], a)
            assert snap[name].dtype == a.dtype
    with h5py.File(path) as f:
        np.testing.assert_array_equal(f["snapshot_times"][()], times)

    root = ET.parse(path.with_suffix(".xmf")).getroot()  # well-formed XML, or this raises
    grids = root.findall("./Domain/Grid/Grid")
    assert [float(g.find("Time").get("Value")) for g in grids] == list(times)
    with h5py.File(path) as f:
        for g, n in zip(grids, sizes):
            assert int(g.find("Topology").get("NumberOfElements")) == n
            items = [d for d in g.iter("DataItem") if d.get("Format") == "HDF"]
            assert items
            for d in items:
                fname, dset = d.text.split(":")
                assert fname == path.name
                assert dset in f, dset
                assert tuple(int(v) for v in d.get("Dimensions").split()) == f[dset].shape
            for slab in (d for d in g.iter("DataItem") if d.get("ItemType") == "HyperSlab"):
                start, stride, count = np.array(slab[0].text.split(), int).reshape(3, -1)
                assert count[0] == n  # a column of the first n rows
            geometry = g.find("Geometry")
            assert geometry.get("GeometryType") == ("XYZ" if dim == 3 else "X_Y_Z")
            vel = [a for a in g.findall("Attribute") if a.get("Name") == "vel"]
            assert len(vel) == 1 and vel[0].get("AttributeType") == "Vector"
        if dim == 2:  # the y column of the x-z plane is zero
            assert (f["xdmf/zeros"][()] == 0).all() and f["xdmf/zeros"].shape[0] >= max(sizes)


def test_file_is_readable_after_an_exception_inside_with(tmp_path):
    path = tmp_path / "crash.h5"
    with pytest.raises(RuntimeError, match="blew up"):
        with H5Output(path, dim=2, buffer_rows=1000) as out:
            for i in range(10):
                out.series("probe", 0.01 * i, p=100.0 * i)
            out.snapshot(0.05, np.zeros((3, 2)), rho=np.ones(3))
            out.series("probe", 0.1, p=1000.0)  # buffered only, written on the way out
            raise RuntimeError("blew up")
    s = read_series(path, "probe")
    np.testing.assert_allclose(s["p"], 100.0 * np.arange(11))
    assert read_snapshot(path, 0)["rho"].tolist() == [1.0, 1.0, 1.0]
    ET.parse(path.with_suffix(".xmf"))


def test_bad_input_is_refused_with_a_reason(tmp_path):
    with pytest.raises(InputError, match="dim"):
        H5Output(tmp_path / "a.h5", dim=4)
    with H5Output(tmp_path / "b.h5", dim=2) as out:
        with pytest.raises(InputError, match=r"\(N, 2\)"):
            out.snapshot(0.0, np.zeros((5, 3)))
        with pytest.raises(InputError, match="rho"):
            out.snapshot(0.0, np.zeros((5, 2)), rho=np.ones(4))
        with pytest.raises(InputError, match="finite"):
            out.snapshot(float("nan"), np.zeros((5, 2)))
        out.series("s", 0.0, a=1.0, b=[1.0, 2.0])
        with pytest.raises(InputError, match="same keys"):
            out.series("s", 0.1, a=1.0)
        with pytest.raises(InputError, match="keeps its length"):
            out.series("s", 0.1, a=1.0, b=[1.0, 2.0, 3.0])
        with pytest.raises(InputError, match="1-D"):
            out.series("s", 0.1, a=np.ones((2, 2)), b=[1.0, 2.0])
        with pytest.raises(InputError, match="name"):
            out.series("bad name", 0.0, a=1.0)
    with pytest.raises(InputError, match="closed"):
        out.series("s", 0.2, a=1.0, b=[1.0, 2.0])
    with pytest.raises(InputError, match="no series"):
        read_series(tmp_path / "b.h5", "nope")
    with pytest.raises(InputError, match="no snapshot"):
        read_snapshot(tmp_path / "b.h5", 0)


def test_csv_and_describe(tmp_path):
    from fluid.output import describe, write_csv

    path = tmp_path / "run.h5"
    with H5Output(path, dim=2, attrs={"dx": 0.02}) as out:
        for i in range(4):
            out.series("gauges", 0.5 * i, eta=[0.1 * i, 0.2], E=float(i))
        out.snapshot(1.0, np.zeros((7, 2)), rho=np.ones(7))
    write_csv(tmp_path / "g.csv", read_series(path, "gauges"))
    lines = (tmp_path / "g.csv").read_text().splitlines()
    assert lines[0] == "t,E,eta_0,eta_1" and len(lines) == 5
    np.testing.assert_array_equal(np.loadtxt(tmp_path / "g.csv", delimiter=",", skiprows=1)[3], [1.5, 3.0, 0.1 * 3, 0.2])
    d = describe(path)
    assert d["attrs"] == {"dim": 2, "dx": 0.02}
    assert d["series"]["gauges"] == {"rows": 4, "keys": {"E": [], "eta": [2]}, "t_s": [0.0, 1.5]}
    assert d["snapshots"] == {"count": 1, "t_s": [1.0, 1.0], "particles_last": 7}


def test_paraview_reader_sees_the_x_z_plane(tmp_path):
    """With VTK installed (not a dependency): its XDMF reader, the one ParaView uses,
    reads 2-D positions as (x, 0, z) and a 2-D velocity as a 3-vector."""
    vtk = pytest.importorskip("vtk")
    from vtk.util.numpy_support import vtk_to_numpy

    path = tmp_path / "pv.h5"
    pos = np.random.default_rng(3).random((9, 2))
    with H5Output(path, dim=2) as out:
        out.snapshot(0.0, pos, vel=2 * pos, kind=np.arange(9, dtype=np.int8))
        out.snapshot(0.5, pos[:5], vel=2 * pos[:5], kind=np.arange(5, dtype=np.int8))
    r = vtk.vtkXdmfReader()
    r.SetFileName(str(path.with_suffix(".xmf")))
    r.UpdateTimeStep(0.5)
    grid = r.GetOutputDataObject(0)
    xyz = vtk_to_numpy(grid.GetPoints().GetData())
    np.testing.assert_array_equal(xyz, np.column_stack([pos[:5, 0], np.zeros(5), pos[:5, 1]]))
    vel = vtk_to_numpy(grid.GetPointData().GetArray("vel"))
    np.testing.assert_array_equal(vel, 2 * np.column_stack([pos[:5, 0], np.zeros(5), pos[:5, 1]]))
