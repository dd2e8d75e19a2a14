"""The Python package against the command line: the same records and diagnostics, field for
field, on every golden programme and every bad programme of the repository.

Run from the repository's root after installing the package (README, "Python"):
    NCSIGHT_BIN=target/release/ncsight python -m pytest crates/ncsight-py/tests
"""

import json
import os
import pathlib
import subprocess

import pytest

import ncsight

ROOT = pathlib.Path(__file__).resolve().parents[3]
BIN = os.environ.get("NCSIGHT_BIN", str(ROOT / "target" / "release" / "ncsight"))
GOLDEN = sorted(p for p in (ROOT / "tests" / "golden").iterdir() if (p / "input.nc").exists())
BAD = sorted((ROOT / "tests" / "bad").glob("*.nc"))


def golden_setup(case):
    """The machine setup a golden case keeps beside its programme, if any."""
    return case / "setup.toml" if (case / "setup.toml").exists() else None


def golden_args(case):
    """The machine and parameters of a golden case (its `args` file: --machine M --param K=V)."""
    words = (case / "args").read_text().split() if (case / "args").exists() else []
    machine, params = "gsk980tdi", []
    for flag, value in zip(words[::2], words[1::2]):
        if flag == "--machine":
            machine = value
        elif flag == "--param":
            params.append(value)
        else:
            raise AssertionError(f"{case.name}: unexpected argument {flag}")
    return machine, params


def cli(*args):
    out = subprocess.run([BIN, *args], capture_output=True, check=False)
    assert out.returncode in (0, 1), out.stderr.decode()
    return [json.loads(line) for line in out.stdout.decode().splitlines() if line.strip()]


def test_the_cli_is_there():
    assert pathlib.Path(BIN).exists(), f"build the command line first (cargo build --release): {BIN}"


@pytest.mark.parametrize("case", GOLDEN, ids=[c.name for c in GOLDEN])
def test_run_gives_the_cli_records(case):
    machine, params = golden_args(case)
    setup = golden_setup(case)
    text = (case / "input.nc").read_bytes()
    records = ncsight.run(text, machine, params=params, setup=setup)
    expected = [json.loads(l) for l in (case / "expected.jsonl").read_text().splitlines() if l.strip()]
    assert records == expected
    # The same from the file, streamed.
    assert list(ncsight.iter_run(case / "input.nc", machine, params=params, setup=setup)) == expected


@pytest.mark.parametrize("case", GOLDEN, ids=[c.name for c in GOLDEN])
def test_check_gives_the_cli_diagnostics(case):
    machine, params = golden_args(case)
    setup = golden_setup(case)
    path = str(case / "input.nc")
    args = ["check", path, "--machine", machine, "--format", "jsonl"]
    for p in params:
        args += ["--param", p]
    if setup:
        args += ["--setup", str(setup)]
    expected = cli(*args)
    assert ncsight.check((case / "input.nc").read_bytes(), machine, params=params, setup=setup, name=path) == expected
    assert list(ncsight.iter_check(pathlib.Path(path), machine, params=params, setup=setup)) == expected


@pytest.mark.parametrize("bad", BAD, ids=[b.name for b in BAD])
def test_an_alarm_is_a_record(bad):
    first = bad.read_bytes().split(b"\n", 1)[0].decode()
    spec = first.strip().strip("()").split()
    code, line, col, machine = spec[1], int(spec[3]), int(spec[5]), spec[7]
    setup = bad.with_suffix(".toml") if bad.with_suffix(".toml").exists() else None
    # A `.args` beside it holds more arguments: here `--param NAME=VALUE` pairs.
    more = bad.with_suffix(".args").read_text().split() if bad.with_suffix(".args").exists() else []
    params = [more[i + 1] for i in range(0, len(more) - 1, 2) if more[i] == "--param"]
    records = ncsight.run(bad.read_bytes(), machine, setup=setup, params=params)
    extra = (["--setup", str(setup)] if setup else []) + more
    assert records == cli("run", str(bad), "--machine", machine, "--format", "jsonl", *extra)
    last = records[-1]
    assert (last["kind"], last["code"], last["line"], last["col"]) == ("alarm", code, line, col)


def test_machines():
    assert set(ncsight.machines()) == {
        "gsk980tdi",
        "gsk988t",
        "fanuc0t",
        "fanuc0m",
        "yasnac-lx3",
        "fanuc0i-tf",
        "fanuc0i-mf",
    }


def test_example_of_the_readme():
    text = (ROOT / "examples" / "gsk980tdi_o0012.nc").read_text(encoding="utf-8", errors="replace")
    records = ncsight.run(text, "gsk980tdi")
    assert len(records) > 0
    assert records == cli("run", str(ROOT / "examples" / "gsk980tdi_o0012.nc"), "--machine", "gsk980tdi", "--format", "jsonl")


def test_usage_errors_raise_value_error():
    with pytest.raises(ValueError, match="unknown machine 'haas'"):
        ncsight.run("G00 X0\n", "haas")
    with pytest.raises(ValueError, match="parameter"):
        ncsight.run("G00 X0\n", "gsk980tdi", params={"99999": 1})
    with pytest.raises(ValueError, match="cannot read no-such-setup.toml"):
        ncsight.run("G00 X0\n", "gsk980tdi", setup="no-such-setup.toml")
    with pytest.raises(ValueError, match="offset 1"):
        ncsight.run("G00 X0\n", "gsk980tdi", setup={"offset": [{"number": 1, "x_mm": float("nan")}]})
    with pytest.raises(ValueError, match="unknown field"):
        ncsight.run("G00 X0\n", "gsk980tdi", setup={"wrok": {}})
    with pytest.raises(TypeError, match="unexpected keyword argument 'subprogram_dir'"):
        ncsight.run("G00 X0\n", "gsk980tdi", subprogram_dir="/tmp")
    with pytest.raises(ValueError, match="--main O12x"):
        ncsight.run("G00 X0\n", "gsk980tdi", main="O12x")
    for bad in (-1, 1.5, True):
        with pytest.raises(ValueError, match="max_blocks"):
            ncsight.run("G00 X0\n", "gsk980tdi", max_blocks=bad)
    with pytest.raises(ValueError, match="variables"):
        ncsight.run("G00 X0\n", "fanuc0m", variables=[(500, 1)])
    with pytest.raises(ValueError, match="name"):
        ncsight.check("G00 X0\n", "fanuc0m", name=3)
    with pytest.raises(ValueError, match="str or bytes"):
        ncsight.run([71, 48], "fanuc0m")
    with pytest.raises(ValueError, match="cannot read"):
        list(ncsight.iter_run(pathlib.Path("/nonexistent/o1.nc"), "gsk980tdi"))


def test_options_as_on_the_command_line(tmp_path):
    sub = tmp_path / "O0100.nc"
    sub.write_text("O0100\nG91 G01 X1. F100.\nG90 M99\n")
    text = "O0001\nG21 G17 G90 G00 X0. Y0. Z10.\nM98 P0030100\n#500 = #500 + 1\nG00 X#500\nM30\n"
    records = ncsight.run(text, "fanuc0m", subprogram_dirs=[tmp_path], variables={500: 4})
    feeds = [r for r in records if r["kind"] == "feed"]
    assert [r["x"] for r in feeds] == [1, 2, 3]
    assert all(r["file"] == str(sub) for r in feeds)
    assert [r["x"] for r in records if r["kind"] == "rapid"][-1] == 5
    missing = ncsight.run(text, "fanuc0m", skip_missing_subprograms=True)
    assert any(r.get("code") == "NCS-W27" for r in missing)


def test_bytes_and_bytearray_are_text():
    text = b"G21 G90 G00 X1. Y2. Z3.\nM30\n"
    assert ncsight.run(text, "fanuc0m") == ncsight.run(bytearray(text), "fanuc0m") == ncsight.run(text.decode(), "fanuc0m")
    # A str is always text, never a path.
    assert list(ncsight.iter_run("G00 X1. Y2. Z3.\nM30\n", "fanuc0m"))[0]["kind"] == "rapid"


def test_a_big_programme_streams(tmp_path):
    big = tmp_path / "holes.nc"
    with big.open("w") as f:
        f.write("G21 G17 G90 G00 X0. Y0. Z10.\nF500.\nG98 G81 X1. Y1. Z-5. R2.\n")
        for i in range(20000):
            f.write(f"X{1 + i % 100}. Y{1 + i // 100}.\n")
        f.write("G80\nM30\n")
    n = 0
    for r in ncsight.iter_run(big, "fanuc0m"):
        n += 1
        if n == 10:
            break
    assert n == 10
    assert sum(1 for _ in ncsight.iter_run(big, "fanuc0m")) > 20000


def test_to_arrays():
    np = pytest.importorskip("numpy")
    records = ncsight.run("G21 G90 G00 X1. Y2. Z3.\nG01 X4. F100.\nM30\n", "fanuc0m")
    a = ncsight.to_arrays(records)
    assert list(a["kind"]) == ["rapid", "feed"]
    assert np.allclose(a["x"], [1.0, 4.0]) and np.allclose(a["z"], [3.0, 3.0])


def test_a_setup_as_a_mapping_is_the_setup_file(tmp_path):
    """setup= takes the file's path or a mapping shaped as it: both give what --setup gives."""
    toml = """[machine.reference]
x_mm = 200.0
z_mm = 100.0

[work]
G54 = { x_mm = 0.0, z_mm = -300.0 }
G55 = { x_mm = 0.0, z_mm = -350.0 }
"""
    mapping = {"machine": {"reference": {"x_mm": 200.0, "z_mm": 100.0}}, "work": {"G54": {"x_mm": 0.0, "z_mm": -300.0}, "G55": {"x_mm": 0, "z_mm": -350}}}
    (tmp_path / "setup.toml").write_text(toml)
    (tmp_path / "p.nc").write_text("G00 X50 Z10\nG55 G00 X50 Z10\nG28 U0 W0\nM30\n")
    expected = cli("run", str(tmp_path / "p.nc"), "--machine", "gsk980tdi", "--format", "jsonl", "--setup", str(tmp_path / "setup.toml"))
    assert any("machine_z" in r for r in expected)
    text = (tmp_path / "p.nc").read_text()
    assert ncsight.run(text, "gsk980tdi", setup=tmp_path / "setup.toml") == expected
    assert ncsight.run(text, "gsk980tdi", setup=mapping) == expected


def test_out_of_range_options_are_value_errors(tmp_path):
    """Issue 32: max_blocks past the native counter is a ValueError (not OverflowError); one folder
    given as a string is that folder (not its letters); a setup mapping nested 5,000 deep is a
    ValueError (not RecursionError)."""
    text = "G00 X50 Z10\nM30\n"
    with pytest.raises(ValueError, match="max_blocks"):
        ncsight.run(text, "gsk980tdi", max_blocks=2**70)
    (tmp_path / "O1234.nc").write_text("O1234\nG00 X40 Z5\nM99\n")
    called = ncsight.run("G00 X50 Z10\nM98 P1234\nM30\n", "gsk980tdi", subprogram_dirs=str(tmp_path))
    assert [r["kind"] for r in called][:2] == ["rapid", "rapid"], called
    assert ncsight.run("G00 X50 Z10\nM98 P1234\nM30\n", "gsk980tdi", subprogram_dirs=tmp_path) == called
    deep: dict = {}
    inner = deep
    for _ in range(5000):
        inner["a"] = {}
        inner = inner["a"]
    with pytest.raises(ValueError, match="nested more than"):
        ncsight.run(text, "gsk980tdi", setup={"machine": deep})
    (tmp_path / "big.toml").write_bytes(b"#" * (16 * 1024 * 1024 + 10))
    with pytest.raises(ValueError, match="at most 16 MiB"):
        ncsight.run(text, "gsk980tdi", setup=tmp_path / "big.toml")


def test_a_macro_body_runs_with_its_arguments():
    body = "O9010\n#3 = #1 + #2\nG01 X#3 F#9\nM99\n"
    records = ncsight.run(body, "fanuc0m", call_args="A1. B2. F100.")
    feeds = [r for r in records if r["kind"] == "feed"]
    assert feeds[0]["x"] == 3 and feeds[0]["f"] == 100
    assert not any(r.get("code") == "NCS-W08" for r in records)
    with pytest.raises(ValueError, match="call_args"):
        ncsight.run(body, "fanuc0m", call_args=["A1."])
