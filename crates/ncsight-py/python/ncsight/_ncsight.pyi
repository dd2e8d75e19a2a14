# Types of the native module (crates/ncsight-py/src/lib.rs); use the functions of `ncsight`.
from os import PathLike
from typing import Iterator, List, Optional, Sequence, Tuple, Union

__version__: str

class Options:
    def __init__(
        self,
        machine: str,
        params: Sequence[str] = ...,
        main: Optional[str] = None,
        subprogram_dirs: Sequence[Union[str, PathLike[str]]] = ...,
        skip_missing_subprograms: bool = False,
        max_blocks: Optional[int] = None,
        variables: Sequence[str] = ...,
        block_delete: bool = False,
        optional_stop: bool = False,
        setup_path: Optional[Union[str, PathLike[str]]] = None,
        setup_toml: Optional[str] = None,
        call_args: Optional[str] = None,
    ) -> None: ...

def machines() -> List[str]: ...
def jsonl_lines(options: Options, mode: str, name: str, text: Optional[Union[str, bytes]] = None, path: Optional[Union[str, PathLike[str]]] = None) -> Tuple[List[str], bool]: ...

class LineStream(Iterator[str]):
    def __init__(self, options: Options, mode: str, name: str, text: Optional[Union[str, bytes]] = None, path: Optional[Union[str, PathLike[str]]] = None) -> None: ...
    def __iter__(self) -> "LineStream": ...
    def __next__(self) -> str: ...
