"""ncsight: see what a CNC programme will do before the machine does it.

The engine is ncsight's Rust core, run as the controller would run the programme (GSK980TDi,
GSK988T, FANUC 0-T and 0-M, YASNAC LX3): every motion, pull-out, spindle phase and alarm.
Records and diagnostics are dicts with exactly the fields of ``ncsight run --format jsonl``
and ``ncsight check --format jsonl`` (see docs/python.md in the repository).

An alarm in the programme is a record (``kind == "alarm"``), not an exception; a mistake in
how a run is asked for (unknown machine, bad parameter, unreadable file) raises ``ValueError``.
"""

from __future__ import annotations

import json
import os
from typing import Any, Dict, Iterable, Iterator, List, Mapping, Optional, Union

from . import _ncsight

__all__ = ["run", "check", "iter_run", "iter_check", "machines", "to_arrays", "__version__"]
__version__: str = _ncsight.__version__

Text = Union[str, bytes]
Params = Union[Mapping[str, float], Iterable[str], None]
PathLike = Union[str, "os.PathLike[str]"]


def machines() -> List[str]:
    """The controller profiles: ``gsk980tdi``, ``gsk988t``, ``fanuc0t``, ``fanuc0m``, ``yasnac-lx3``, ``fanuc0i-tf``, ``fanuc0i-mf``."""
    return list(_ncsight.machines())


def _params(params: Params) -> List[str]:
    """Parameter overrides as the command line takes them: ``{"18.6": 1}`` or ``["18.6=1"]``."""
    if params is None:
        return []
    if isinstance(params, Mapping):
        return [f"{k}={_number(v)}" for k, v in params.items()]
    if isinstance(params, (str, bytes)):
        raise ValueError("params: a mapping such as {'19': 10} or a list such as ['19=10']")
    return [str(p) for p in params]


def _number(v: Any) -> str:
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise ValueError(f"a parameter's value is a number, not {v!r}")
    return repr(float(v)) if isinstance(v, float) else str(v)


def _variables(variables: Optional[Mapping[int, float]]) -> List[str]:
    if not variables:
        return []
    return [f"{int(k)}={_number(v)}" for k, v in variables.items()]


def _toml_key(k: Any) -> str:
    k = str(k)
    return k if k and all(c.isalnum() or c in "_-" for c in k) else json.dumps(k)


# How deep a setup mapping may nest: a real setup nests three deep (``machine.limits.x_mm``).
_MAX_SETUP_DEPTH = 8

# The most blocks the runaway guard may allow: the native half's unsigned 64-bit counter.
_MAX_BLOCKS = 2**64 - 1


def _toml_value(v: Any, depth: int = 0) -> str:
    """A value as TOML writes it inline (tables as inline tables)."""
    if depth > _MAX_SETUP_DEPTH:
        raise ValueError(f"setup: nested more than {_MAX_SETUP_DEPTH} deep; a setup file nests three deep (machine.limits.x_mm)")
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v) if isinstance(v, int) else repr(float(v))
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, Mapping):
        return "{ " + ", ".join(f"{_toml_key(k)} = {_toml_value(x, depth + 1)}" for k, x in v.items()) + " }"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x, depth + 1) for x in v) + "]"
    raise ValueError(f"setup: {v!r} is not a number, string, list or mapping")


def _setup(setup: Any) -> "tuple[Optional[str], Optional[str]]":
    """The setup as a path to its TOML file, or a mapping shaped as the file (``{"work": {"G54":
    {"x_mm": 0, "z_mm": -400}}, "offset": [{"number": 1, "x_mm": -150}]}``) written as TOML."""
    if setup is None:
        return None, None
    if isinstance(setup, (str, os.PathLike)):
        return os.fspath(setup), None
    if isinstance(setup, Mapping):
        return None, "\n".join(f"{_toml_key(k)} = {_toml_value(v)}" for k, v in setup.items()) + "\n"
    raise ValueError("setup: the path of a setup file (TOML), or a mapping shaped as one")


_OPTIONS = ("main", "subprogram_dirs", "skip_missing_subprograms", "max_blocks", "variables", "call_args", "block_delete", "optional_stop")


def _options(caller: str, machine: str, params: Params, setup: Any, options: Mapping[str, Any]) -> Any:
    """The run as the native half takes it; the keyword options are those of the command line
    (see the stub, ``__init__.pyi``, for their types)."""
    unknown = sorted(set(options) - set(_OPTIONS))
    if unknown:
        raise TypeError(f"{caller}() got an unexpected keyword argument {unknown[0]!r} (options: {', '.join(_OPTIONS)})")
    setup_path, setup_toml = _setup(setup)
    if not isinstance(machine, str):
        raise ValueError(f"machine: one of {', '.join(machines())}")
    main = options.get("main")
    max_blocks = options.get("max_blocks")
    if max_blocks is not None and (isinstance(max_blocks, bool) or not isinstance(max_blocks, int) or not 0 <= max_blocks <= _MAX_BLOCKS):
        raise ValueError(f"max_blocks: a whole number of blocks, 0 to {_MAX_BLOCKS}, not {max_blocks!r}")
    subprogram_dirs = options.get("subprogram_dirs") or []
    # One folder given as a string or path, not a list: taken as that folder (a string is not
    # read letter by letter).
    if isinstance(subprogram_dirs, (str, bytes, os.PathLike)):
        subprogram_dirs = [subprogram_dirs]
    if not isinstance(subprogram_dirs, (list, tuple)):
        raise ValueError(f"subprogram_dirs: a list of folders, not {subprogram_dirs!r}")
    variables = options.get("variables")
    if variables is not None and not isinstance(variables, Mapping):
        raise ValueError("variables: a mapping such as {500: 1.5, 1002: 1}")
    call_args = options.get("call_args")
    if call_args is not None and not isinstance(call_args, str):
        raise ValueError(f"call_args: the arguments as a G65 block writes them after P, such as 'A1. B2.', not {call_args!r}")
    if main is not None and (isinstance(main, bool) or not isinstance(main, (int, str))):
        raise ValueError(f"main: a programme number such as 1234 or 'O1234', not {main!r}")
    return _ncsight.Options(
        machine,
        params=_params(params),
        main=None if main is None else str(main),
        subprogram_dirs=[os.fsdecode(os.fspath(d)) for d in subprogram_dirs],
        skip_missing_subprograms=bool(options.get("skip_missing_subprograms", False)),
        max_blocks=max_blocks,
        variables=_variables(variables),
        block_delete=bool(options.get("block_delete", False)),
        optional_stop=bool(options.get("optional_stop", False)),
        setup_path=setup_path,
        setup_toml=setup_toml,
        call_args=call_args,
    )


def run(text: Text, machine: str, params: Params = None, setup: Any = None, **options: Any) -> List[Dict[str, Any]]:
    """Run a programme's text on ``machine``: its records and diagnostics, in order, as
    ``ncsight run --format jsonl`` gives them. ``text`` is a str, or bytes as read from a file
    (GBK comments and all)."""
    lines, _ = _ncsight.jsonl_lines(_options("run", machine, params, setup, options), "run", "<text>", text=text)
    return [json.loads(line) for line in lines]


def check(text: Text, machine: str, params: Params = None, setup: Any = None, *, name: str = "<text>", **options: Any) -> List[Dict[str, Any]]:
    """Check a programme's text on ``machine``: its diagnostics as ``ncsight check --format
    jsonl`` gives them (``name`` is their ``file``)."""
    if not isinstance(name, str):
        raise ValueError(f"name: the file name the diagnostics give, a str, not {name!r}")
    lines, _ = _ncsight.jsonl_lines(_options("check", machine, params, setup, options), "check", name, text=text)
    return [json.loads(line) for line in lines]


def _stream(mode: str, source: Union[Text, "os.PathLike[str]"], name: Optional[str], opts: Any) -> Iterator[Dict[str, Any]]:
    if name is not None and not isinstance(name, str):
        raise ValueError(f"name: the file name the diagnostics give, a str, not {name!r}")
    # A str is the programme's text; a path is a pathlib.Path (or any os.PathLike).
    if isinstance(source, (str, bytes, bytearray)):
        stream = _ncsight.LineStream(opts, mode, name or "<text>", text=source)
    else:
        path = os.fspath(source)
        stream = _ncsight.LineStream(opts, mode, name or path, path=path)
    return (json.loads(line) for line in stream)


def iter_run(source: Union[Text, "os.PathLike[str]"], machine: str, params: Params = None, setup: Any = None, **options: Any) -> Iterator[Dict[str, Any]]:
    """Like :func:`run`, one record at a time while the programme runs on another thread, in
    bounded memory. ``source`` is the text (str or bytes) or a path (a ``pathlib.Path``: a str is
    always text): a file is read as it runs, and jumps back read it again, so a programme of any
    size fits. Stop iterating and the run stops (at the end of the line being run)."""
    return _stream("run", source, None, _options("iter_run", machine, params, setup, options))


def iter_check(source: Union[Text, "os.PathLike[str]"], machine: str, params: Params = None, setup: Any = None, *, name: Optional[str] = None, **options: Any) -> Iterator[Dict[str, Any]]:
    """Like :func:`check`, one diagnostic at a time; a path is read as the check goes."""
    return _stream("check", source, name, _options("iter_check", machine, params, setup, options))


_ARRAY_FIELDS = ("line", "t", "x", "y", "z")


def to_arrays(records: Iterable[Mapping[str, Any]]) -> Dict[str, Any]:
    """The motion records (rapid, feed, arc, thread, thread_arc) as NumPy arrays: ``kind``
    (str), ``line``, ``t`` (s at the record's end), ``x``, ``y``, ``z`` (its end point; an axis
    a record does not name is 0, as JSONL leaves it out). Needs numpy."""
    import numpy as np  # optional dependency: pip install numpy

    moves = [r for r in records if r.get("kind") in ("rapid", "feed", "arc", "thread", "thread_arc")]
    out: Dict[str, Any] = {"kind": np.array([r["kind"] for r in moves], dtype=str)}
    for f in _ARRAY_FIELDS:
        out[f] = np.array([float(r.get(f, 0.0)) for r in moves], dtype=np.float64)
    return out
