# The stub of the Python module bookspin (docs/python.md), beside the module in BUILD/python/.
# Arrays are numpy float64 (images uint8); shapes in the comments: N rows.
import os
from typing import Any, Iterator, Mapping, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

ArrayLike = npt.ArrayLike
Array = npt.NDArray[np.float64]
Scalar = Union[bool, int, float, str]
Image = npt.NDArray[np.uint8]
SceneArg = Union[str, os.PathLike[str]]
Overrides = Optional[Mapping[str, Union[Scalar, Sequence[Scalar]]]]

__version__: str
"""bookspin's version (VERSION): the wheel's, `bookspin --version`'s and a judgement's."""

class Error(ValueError):
    """Bad input: the command line's one line ("FILE:LINE: KEY: reason")."""

def exact_motion(moments: ArrayLike, omega0: ArrayLike, t: ArrayLike) -> dict[str, Array]:
    """moments (3,), omega0 (3,) body frame rad per time unit, t (N,) ->
    q (N, 4) w, x, y, z body to world; omega_body (N, 3); omega_world (N, 3);
    L_world (N, 3); E (N,)."""

def simulate(
    scene: Union[str, os.PathLike[str]],
    overrides: Optional[Mapping[str, Union[Scalar, Sequence[Scalar]]]] = None,
) -> dict[str, Array]:
    """Every column of `bookspin simulate`'s CSV, each (N,), one value per frame."""

Cell = Union[float, str, None]

class Fit:
    """A recording's fit (bookspin.fit)."""
    recording: str
    """The recording's name (its file-safe stem)."""
    body: dict[str, Cell]
    """The -fit-body.csv row, keyed by its columns."""
    tosses: list[dict[str, Cell]]
    """The -fit.csv rows, one per toss."""
    summary: list[str]
    """The lines the command prints before "wrote ..."."""
    charts: list[dict[str, Union[Array, str]]]
    """Per toss: recording (str, its own recording's name); t (N,) s, that recording's own
    time; measured, fitted (N, 3) rad/s phone frame; curve_t (M,);
    curve (M, 3); flips (K,) s."""

def fit(
    recording: Union[
        str, os.PathLike[str], tuple[ArrayLike, ArrayLike], Sequence[Union[str, os.PathLike[str]]]
    ],
    drag: str = "linear",
    tosses: Union[Sequence[tuple[float, float]], ArrayLike, str, None] = None,
    moments: Optional[ArrayLike] = None,
) -> Fit:
    """A phyphox export, a t,wx,wy,wz CSV, or (t (N,) s, omega (N, 3) rad/s phone frame),
    fitted as `bookspin fit` fits it; a list of paths: recordings of one body fitted as one."""

def read_gyro_csv(text: str | bytes, file: str = "recording.csv") -> dict[str, Array]:
    """A recording's CSV text read as `bookspin fit` reads a file: {"t": (N,) s, "omega": (N, 3)
    rad/s}; bookspin.Error with the reader's line naming `file`, row and column."""

class PreparedRecording:
    """A recording prepared once for the live fit (bookspin.prepare_recording)."""
    name: str
    """Its file-safe stem."""
    source: str
    """The file read."""
    flights: int
    """Its free flights found."""
    nbytes: int
    """The bytes it holds (its samples in flight and its values)."""

def prepare_recording(recording: Union[str, os.PathLike[str]]) -> PreparedRecording:
    """What a recording needs of its own for the live fit, done once: read as `bookspin fit`
    reads it, its flights found, its own joint fit; bookspin.Error with the command's line for
    a recording it cannot read."""

class LiveFit:
    """A live pooled fit (bookspin.live_fit)."""
    body: dict[str, Optional[float]]
    """I1_over_I3, I2_over_I3, I3_over_I3, I1_sigma, I2_sigma (the covariance's; None where it
    cannot be computed), axis1_x ... axis3_z, recordings, tosses."""
    tosses: list[dict[str, Union[float, int, str, None]]]
    """One per flight: recording, flight, toss, t_start, t_end, omega0_x/y/z, drag_rate,
    half_period_measured, half_period_fitted, residual_rms."""

def live_fit(recordings: Sequence[PreparedRecording],
             start: Optional[LiveFit] = None) -> LiveFit:
    """The recordings' pooled body in one joint solve warm-started from `start` (a previous
    live fit) or, with none, from a grown joint fit: near `bookspin fit`'s, not its numbers."""

flight_requirements: dict[str, float]
"""What the finder needs to keep a flight (the defaults every door uses): flight_omega rad/s
(turning at least this fast throughout), min_flight s (at least this long), rest_omega rad/s
(slower than this is at rest)."""

class Frames(Iterator[tuple[float, Image]]):
    """The iterator bookspin.frames returns."""
    def __iter__(self) -> "Frames": ...
    def __next__(self) -> tuple[float, Image]:
        """(t in time units, image (H, W, 3) RGB uint8, top row first)."""
    def close(self) -> None:
        """Stops the frames early; later next() calls raise StopIteration."""

def frames(scene: SceneArg, overrides: Overrides = None) -> Frames:
    """The frames `bookspin render` encodes, one at a time: (t, image (H, W, 3) uint8)."""

def render(
    scene: SceneArg,
    out: Union[str, os.PathLike[str]],
    overrides: Overrides = None,
    png: bool = False,
    progress: bool = True,
) -> str:
    """`bookspin render SCENE -o OUT` (png=False: --no-png); the MP4's path."""

class flipcheck:  # a submodule: bookspin.flipcheck
    scenario_dir: str
    """The folder scenarios are looked up in by name: bookspin-scenarios/ beside the module, the
    copy of scenes/flipcheck/ it carries."""

    @staticmethod
    def scenarios(directory: Optional[Union[str, os.PathLike[str]]] = None) -> list[str]: ...
    @staticmethod
    def export(
        scenario: Union[str, os.PathLike[str]],
        directory: Optional[Union[str, os.PathLike[str]]] = None,
    ) -> tuple[dict[str, Any], dict[str, Array]]:
        """(the scenario's JSON as a dict, t (N,), q (N, 4), omega_body (N, 3),
        omega_world (N, 3), L_world (N, 3), E (N,))."""
    @staticmethod
    def judge(
        scenario: Union[str, os.PathLike[str]],
        t: ArrayLike,
        q: ArrayLike,
        omega_world: ArrayLike,
        directory: Optional[Union[str, os.PathLike[str]]] = None,
        motion: str = "motion",
    ) -> dict[str, Union[str, int, float, None]]:
        """t (N,), q (N, 4) w, x, y, z, omega_world (N, 3) -> the judgement CSV's row."""
    @staticmethod
    def assert_passes(
        scenario: Union[str, os.PathLike[str]],
        t: ArrayLike,
        q: ArrayLike,
        omega_world: ArrayLike,
        directory: Optional[Union[str, os.PathLike[str]]] = None,
        motion: str = "motion",
    ) -> dict[str, Union[str, int, float, None]]:
        """judge(...), or AssertionError with the command line's line (its reasons) on a fail."""
