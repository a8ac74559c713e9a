# Type stubs of the lumibench package (docs/python.md). The functions are
# those of lumibench._core (python/src/) and lumibench.run (__init__.py);
# python/tests/test_api.py holds this file's names and keywords to the module's.
import os
from typing import Any, Mapping, Optional, Sequence, Tuple, Union

import numpy
import numpy.typing
import pandas

_Image = numpy.typing.NDArray[Union[numpy.float32, numpy.float64]]
_Path = Union[str, os.PathLike[str]]
__version__: str  # the project's version (CMakeLists.txt)

class InputError(ValueError):
    """Bad input: a file, a SPEC, a keyword's value (the CLI's exit code 2)."""

class Error(RuntimeError):
    """A device, internal or output failure (the CLI's exit code 1)."""

class Luminaire:
    @staticmethod
    def load(path: str) -> Luminaire: ...
    @property
    def path(self) -> str: ...
    @property
    def format(self) -> str: ...
    @property
    def symmetry(self) -> str: ...
    @property
    def isym(self) -> int: ...
    @property
    def flux_lm(self) -> float: ...
    @property
    def declared_flux_lm(self) -> float: ...
    @property
    def max_cd(self) -> float: ...
    @property
    def opening_shape(self) -> str: ...
    @property
    def opening_size(self) -> Tuple[float, float, float]: ...
    @property
    def c(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def gamma(self) -> numpy.typing.NDArray[numpy.float64]: ...
    @property
    def candela(self) -> numpy.typing.NDArray[numpy.float64]: ...
    def intensity(self, c: float, gamma: float) -> float: ...

class Scene:
    def __init__(
        self,
        *,
        height: float,
        rotation: Union[float, str],
        size: Union[Tuple[float, float], Sequence[float], str] = (1.0, 1.0),
        shape: Optional[str] = None,
        res: int = 256,
        extent: float = 5.0,
        kind: str = "diffuse",
        alpha: Optional[float] = None,
        eye: Optional[Tuple[float, float, float]] = None,
        albedo: Optional[float] = None,
    ) -> None: ...
    @property
    def height(self) -> float: ...
    @property
    def rotation(self) -> float: ...
    @property
    def size(self) -> Union[Tuple[float, float], str]: ...
    @property
    def shape(self) -> str: ...
    @property
    def res(self) -> int: ...
    @property
    def extent(self) -> float: ...
    @property
    def kind(self) -> str: ...

def devices() -> list[dict[str, Any]]: ...
def methods() -> list[dict[str, Any]]: ...
def render(
    luminaire: Luminaire,
    scene: Scene,
    spec: str,
    *,
    precision: str = "float",
    device: Optional[int] = None,
    seed: Optional[int] = None,
    reps: int = 5,
    cache: bool = True,
) -> Tuple[_Image, dict[str, Any]]: ...
def reference(
    luminaire: Luminaire,
    scene: Scene,
    *,
    spec: str = "reference",
    precision: str = "float",
    device: Optional[int] = None,
    cache: bool = True,
) -> Tuple[_Image, _Image, dict[str, Any]]: ...
def compare(ref: _Image, img: _Image, *, flip: bool = True) -> dict[str, Any]: ...
def read_exr(path: str) -> numpy.typing.NDArray[numpy.float32]: ...
def write_exr(path: str, array: _Image) -> None: ...
def run(
    experiment: Union[_Path, Mapping[str, Any]],
    out: _Path,
    *,
    luminaires: Optional[str] = None,
    shard: str = "1/1",
    res: Optional[int] = None,
    reps: Optional[int] = None,
    time_res: Optional[int] = None,
    seeds: Optional[int] = None,
    device: Optional[int] = None,
    report: bool = True,
    progress: bool = False,
) -> pandas.DataFrame: ...
def bench(
    *,
    luminaire: str = "batwing",
    height: float = 1.0,
    rotation: str = "3pi/4",
    res: int = 512,
    reps: int = 5,
    samples: int = 32,
    rounds: int = 3,
    local: str = "8x8",
    device: Optional[int] = None,
    quick: bool = False,
) -> dict[str, Any]: ...
