# The package's types (the implementation: __init__.py).
import os
import sys
from typing import Any, Dict, Iterable, Iterator, List, Mapping, Optional, Sequence, Union

if sys.version_info >= (3, 11):
    from typing import TypedDict, Unpack
else:
    from typing_extensions import TypedDict, Unpack

__version__: str

Text = Union[str, bytes]
Params = Union[Mapping[str, float], Iterable[str], None]
PathLike = Union[str, os.PathLike[str]]
# A setup file's path, or a mapping shaped as the file (docs/setup.md).
Setup = Union[str, os.PathLike[str], Mapping[str, Any], None]

class _Options(TypedDict, total=False):
    """The command line's options: --main, --subprogram-dir, --skip-missing-subprograms,
    --max-blocks, --var, --call-args, --block-delete, --optional-stop."""

    main: Union[int, str]
    subprogram_dirs: Union[PathLike, Sequence[PathLike]]
    skip_missing_subprograms: bool
    max_blocks: int
    variables: Mapping[int, float]
    call_args: str
    block_delete: bool
    optional_stop: bool

def machines() -> List[str]: ...
def run(text: Text, machine: str, params: Params = None, setup: Setup = None, **options: Unpack[_Options]) -> List[Dict[str, Any]]: ...
def check(text: Text, machine: str, params: Params = None, setup: Setup = None, *, name: str = "<text>", **options: Unpack[_Options]) -> List[Dict[str, Any]]: ...
def iter_run(source: Union[Text, os.PathLike[str]], machine: str, params: Params = None, setup: Setup = None, **options: Unpack[_Options]) -> Iterator[Dict[str, Any]]: ...
def iter_check(source: Union[Text, os.PathLike[str]], machine: str, params: Params = None, setup: Setup = None, *, name: Optional[str] = None, **options: Unpack[_Options]) -> Iterator[Dict[str, Any]]: ...
def to_arrays(records: Iterable[Mapping[str, Any]]) -> Dict[str, Any]: ...
