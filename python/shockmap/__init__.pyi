"""shockmap: modal impact runs, scenes, studies and their database from Python.

Every quantity is in SI units (s, m, N, N s, J); ratios (R_k, R_ftrunc) have none.
Runs release the GIL; bad input raises InputError with the command line's message.
"""

import os
from typing import Any, Callable, Dict, List, Literal, Mapping, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt
import pandas as pd

__version__: str
__all__: List[str]
DEFAULT_DATABASE: str

PathLike = Union[str, "os.PathLike[str]"]
FloatArray = npt.NDArray[np.float64]
Status = Literal["ok", "diverged", "unstable", "failed", "reference_unconverged"]
ProgressCallback = Callable[[str, float, float], None]

class InputError(ValueError):
    """Bad input: the message names the file, key or flag, the value and what is allowed."""

class DatabaseError(RuntimeError):
    """A study database that is missing, foreign, corrupt, newer, locked or refuses a query."""

class Comparison:
    """One run of the paper's problem scored against its semi-analytical reference."""

    @property
    def status(self) -> str:
        """ok, diverged, unstable, failed or reference_unconverged."""
    @property
    def message(self) -> str:
        """Why the run failed or diverged (empty when ok)."""
    @property
    def err(self) -> Optional[float]:
        """Err, spectral error of the tip displacement (paper eq. 8); None when not scored."""
    @property
    def srf(self) -> Optional[float]:
        """SRf, impulse ratio of the first shock (paper eq. 9); None when not scored."""
    @property
    def pfr(self) -> Optional[float]:
        """Peak-force ratio of the first shock; None when not scored."""
    @property
    def scores(self) -> Dict[str, Optional[float]]:
        """Every score of the registry by name (err, srf, pfr, ...)."""
    @property
    def n_modes(self) -> int:
        """Modes kept below f_trunc."""
    @property
    def n_elements(self) -> int:
        """Finite elements of the beam."""
    @property
    def dt_used_s(self) -> float:
        """Time step used, s (shortened so the run ends on the window)."""
    @property
    def steps(self) -> int:
        """Time steps taken."""
    @property
    def cpu_s(self) -> float:
        """CPU time of the numerical run, s."""
    @property
    def wall_s(self) -> float:
        """Wall time of the numerical run, s."""
    @property
    def dt_paper_s(self) -> float:
        """The paper's stability bound 1/(4 f_trunc), s."""
    @property
    def dt_sharp_s(self) -> float:
        """The sharp stability bound 2/omega_max, s."""
    @property
    def shocks_numerical(self) -> List[Dict[str, Any]]:
        """The numerical run's shocks: start_s, end_s, impulse_n_s, peak_force_n, rebounds, ..."""
    @property
    def shocks_reference(self) -> List[Dict[str, Any]]:
        """The reference's shocks, as shocks_numerical."""
    @property
    def numerical(self) -> Dict[str, FloatArray]:
        """Histories of the run: t_s, tip_displacement_m, tip_velocity_m_s, contact_force_n,
        kinetic_j, strain_j, contact_j, dissipated_j (those recorded).

        Read-only arrays over the run's memory; they stay valid after the Comparison is deleted.
        """
    @property
    def reference(self) -> Dict[str, FloatArray]:
        """The reference's histories: t_s, tip_displacement_m, contact_force_n."""
    @property
    def reference_r_fref(self) -> float:
        """The reference's truncation f_ref / f1."""
    @property
    def reference_difference(self) -> float:
        """The reference against its coarser check, as a fraction of the amplitude."""

def compare(
    rk: float,
    rftrunc: float,
    *,
    dt: Optional[float] = None,
    dt_factor: float = 0.1,
    dt_rule: Literal["paper", "sharp"] = "sharp",
    window_s: float = 0.06,
    scheme: Literal["explicit-modal", "implicit-full"] = "explicit-modal",
    rfref: Optional[float] = None,
    elements: int = 0,
) -> Comparison:
    """Run the paper's problem at R_k, R_ftrunc and score it, as `shockmap compare`.

    dt (s) excludes dt_factor/dt_rule; rfref None takes the command line's default.
    Releases the GIL. Raises InputError on a bad value.
    """

class Scene:
    """A scene (beams, contact zones, effects, solver, outputs), checked as the file reader does."""

    @classmethod
    def load(cls, path: PathLike) -> "Scene":
        """Read and check a scene file; InputError names the file, key, value and what's allowed."""
    @classmethod
    def from_dict(cls, scene: Mapping[str, Any], path: str = "<dict>") -> "Scene":
        """Check a scene given as a dict (path names it in messages and resolves relative files)."""
    def to_dict(self) -> Dict[str, Any]:
        """The scene as a dict, in the file's format."""
    def set(self, key: str, value: Union[float, int, bool]) -> "Scene":
        """Set a value by its path (e.g. "bundle.wire.stiffness_n_per_m", "zones[0].gap_m").

        The value takes the type already there and the scene is checked again; InputError
        names the path and the value, and leaves the scene as it was. Returns the scene.
        """
    @property
    def name(self) -> str:
        """The scene's name."""
    @property
    def path(self) -> str:
        """The file (or the name given to from_dict) that messages name."""

class SceneRun:
    """The result of simulate()."""

    @property
    def status(self) -> str:
        """ok, diverged, unstable or failed."""
    @property
    def message(self) -> str:
        """Why the run failed or diverged (empty when ok)."""
    @property
    def steps(self) -> int:
        """Time steps taken."""
    @property
    def dt_used_s(self) -> float:
        """Time step used, s."""
    @property
    def dt_s(self) -> float:
        """Time step used, s (as in summary)."""
    @property
    def dt_paper_s(self) -> float:
        """The paper's stability bound 1/(4 f_trunc), s."""
    @property
    def dt_sharp_s(self) -> float:
        """The sharp stability bound 2/omega_max, s."""
    @property
    def max_energy_ratio(self) -> float:
        """Largest total energy over the initial energy."""
    @property
    def distinct_bases(self) -> int:
        """Modal bases computed (identical beams share one)."""
    @property
    def build_wall_s(self) -> float:
        """Wall time of building the model, s."""
    @property
    def coordinates(self) -> int:
        """Modal coordinates of the model."""
    @property
    def modes_per_beam(self) -> List[int]:
        """Modes kept on each beam."""
    @property
    def cpu_s(self) -> float:
        """CPU time of the run, s."""
    @property
    def wall_s(self) -> float:
        """Wall time of the run, s."""
    summary: Dict[str, Any]
    """The summary, as `shockmap simulate --json` prints it."""
    @property
    def zones(self) -> pd.DataFrame:
        """One row per contact zone: its name, position, max_force_n (when tracked), shocks and
        impact statistics when the scene asks for them."""
    @property
    def histories(self) -> Dict[str, FloatArray]:
        """t_s, each displacement output NAME_m (NAME_velocity_m_s), each zone's force ZONE_n and
        the energies when recorded (kinetic_j, strain_j, contact_j, dissipated_j,
        external_work_j), named as `simulate --out`'s CSV columns; read-only, valid after the
        SceneRun is deleted."""

def simulate(scene: Union[Scene, PathLike], progress: bool = False) -> SceneRun:
    """Run a scene (or a scene file), as `shockmap simulate`. Releases the GIL. SIGINT, SIGTERM
    or SIGHUP stops it and goes to the program's handler (Ctrl-C: KeyboardInterrupt); when that
    handler returns, InterruptedError (a stopped simulation has no result)."""

class Study:
    """A study file of any kind: canonical, scene_sweep or scene_ensemble."""

    @classmethod
    def load(cls, path: PathLike) -> "Study":
        """Read and check a study file; InputError names the file, key, value and what's allowed."""
    @property
    def name(self) -> str:
        """The study's name in the database."""
    @property
    def kind(self) -> str:
        """canonical, scene_sweep or scene_ensemble."""
    @property
    def path(self) -> str:
        """The study file."""
    def run(
        self,
        db: PathLike = "shockmap.db",
        jobs: Optional[int] = None,
        retry_failed: bool = False,
        progress: Union[bool, ProgressCallback] = False,
    ) -> Dict[str, Any]:
        """Compute the points the database lacks, as `shockmap study run` (resume, lease).

        jobs None: one worker per core. progress True prints the tool's lines on stderr; a
        callable gets (phase, done, total). Ctrl-C stops as SIGINT does (points in flight
        stored) and raises KeyboardInterrupt. Returns the run's summary (points_in_study,
        points_computed, ok, diverged, unstable, failed, reference_unconverged, wall_s, ...).
        """

def query(db: PathLike, sql: str, *params: Union[None, int, float, str]) -> pd.DataFrame:
    """One read-only statement, as `shockmap query`, with ?1, ?2 ... bound to params (NULL,
    integer, real or text as given; InputError for another type).

    DatabaseError if it would write; df.attrs["units"] maps declared columns to units.
    """

def results(db: PathLike = "shockmap.db", study: Optional[str] = None) -> pd.DataFrame:
    """The study's rows of its view (results, scene_results or ensemble_results), by point.

    df.attrs["units"] maps each declared column to its unit ("s", "N", "N s"; "" for none).
    """

def criteria(
    db: PathLike = "shockmap.db", study: Optional[str] = None, **thresholds: float
) -> pd.DataFrame:
    """The validity boundary, one row per R_k, as `shockmap criteria derive --out` writes it.

    thresholds (err_max=0.1, srf_min=0.8, ...) over the study's own; attrs["criteria"] holds
    the whole derivation (fit, time step).
    """

def sizing(
    db: PathLike = "shockmap.db",
    study: Optional[str] = None,
    wear: bool = False,
    quantile: float = 0.95,
    confidence: float = 0.95,
) -> pd.DataFrame:
    """Per state, setting and zone sizing statistics of an ensemble, as `shockmap sizing
    --format csv` (the wear table of `sizing --wear` with wear=True)."""

def reference(db: PathLike, reference_id: int, scene: bool = False) -> Dict[str, FloatArray]:
    """A stored reference's signals by id in reference_runs (scene_references with scene=True):
    t_s and tip_displacement_m, contact_force_n (a scene's scored displacement and force)."""

def point(db: PathLike, study: str, point_id: int) -> Comparison:
    """A stored point computed again against its stored reference (as `shockmap export point`)."""

SCENE_CRITERIA: str

def report(
    db: PathLike = "shockmap.db",
    study: Optional[str] = None,
    *,
    out: PathLike,
    progress: Union[bool, ProgressCallback] = False,
    **thresholds: float,
) -> str:
    """The HTML report of a stored study into `out`, as `shockmap report`; returns the path of
    its index.html. thresholds (err_max=0.1, ...) over the study's own."""

def check_advice(
    study: PathLike,
    db: PathLike = "shockmap.db",
    *,
    criteria: Optional[PathLike] = None,
    members: Optional[int] = None,
    window_s: Optional[float] = None,
    states: Union[None, str, Sequence[str]] = None,
    jobs: Optional[int] = None,
    quantile: Optional[float] = None,
    tolerance: Optional[float] = None,
    max_rungs: Optional[int] = None,
    record: Optional[PathLike] = None,
    write_study: Optional[PathLike] = None,
    progress: Union[bool, ProgressCallback] = False,
) -> Dict[str, Any]:
    """The advice for an ensemble study's scene checked on its members, as `shockmap
    check-advice`: dt_ratio, r_ftrunc (per beam), warnings, and the check's verdict, table
    (DataFrame), factors, cpu_s_per_member, converged, undecided (not when write_study)."""
