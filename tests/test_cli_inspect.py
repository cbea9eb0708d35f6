"""`cosim inspect`: the contents of an output file as JSON, its series as CSV."""

import json

import numpy as np

from cosim.cli import main
from fluid.output import H5Output


def test_inspect_prints_json_and_writes_csv(tmp_path, capsys):
    path = tmp_path / "run.h5"
    with H5Output(path, dim=3, attrs={"dx": 0.01}) as out:
        out.series("bodies/box", 0.0, com=[0.0, 0.0, 1.0])
        out.series("bodies/box", 0.1, com=[0.0, 0.0, 0.9])
        out.snapshot(0.0, np.zeros((4, 3)))
    assert main(["inspect", str(path), "--csv", str(tmp_path / "csv")]) == 0
    info = json.loads(capsys.readouterr().out)
    assert info["series"]["bodies/box"] == {"rows": 2, "keys": {"com": [3]}, "t_s": [0.0, 0.1]}
    assert info["snapshots"]["count"] == 1 and info["attrs"]["dx"] == 0.01
    table = np.loadtxt(tmp_path / "csv" / "bodies__box.csv", delimiter=",", skiprows=1)
    np.testing.assert_array_equal(table[1], [0.1, 0.0, 0.0, 0.9])
    # units the file states go into the header (the time's always: s)
    with H5Output(tmp_path / "u.h5", dim=2) as out:
        out.annotate("probes/motion", "box.heave", units="m")
        out.series("probes/motion", 0.0, **{"box.heave": 0.0, "box.pitch": 1.0})
    assert main(["inspect", str(tmp_path / "u.h5"), "--csv", str(tmp_path / "u")]) == 0
    capsys.readouterr()
    head = (tmp_path / "u" / "probes__motion.csv").read_text().splitlines()[0]
    assert head == "t [s],box.heave [m],box.pitch"


def test_inspect_names_a_file_that_is_not_an_output(tmp_path, capsys):
    bad = tmp_path / "x.h5"
    bad.write_text("not hdf5")
    assert main(["inspect", str(bad)]) == 2
    assert "not an output file" in capsys.readouterr().err
