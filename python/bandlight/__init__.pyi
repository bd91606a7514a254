# SPDX-License-Identifier: BSD-3-Clause
"""Type stubs of the bandlight package (the extension is python/src/*.cpp).

tests/python/test_stubs.py checks that every public name, parameter and
keyword-only marker here matches the extension.
"""

import os
from dataclasses import dataclass
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, TypedDict, Union, overload

import numpy as np
import numpy.typing as npt
import PyOpenColorIO as OCIO

__version__: str

FloatArray = npt.NDArray[np.float64]
Float32Array = npt.NDArray[np.float32]
StrPath = Union[str, "os.PathLike[str]"]

#: A light: a built-in name or a spectrum file (str, as --illuminant takes
#: it), a spectrum file (os.PathLike), or a Spectrum.
LightLike = Union[str, "os.PathLike[str]", "Spectrum"]
#: Remittances: a test colour or file (str: "TCS01", "TCS", "chart.sp"), a
#: file (os.PathLike), one Spectrum, or a sequence of them.
RemittancesLike = Union[str, "os.PathLike[str]", "Spectrum", Sequence["Spectrum"]]
#: Bands: a BandSet, edges in nm ("400,500,600,700" or a sequence), or None
#: for the lecture's VB/VG/VR.
BandsLike = Union["BandSet", str, Sequence[float], None]
#: An observer: "1931" (CIE 1931 2 degree) or "1964" (CIE 1964 10 degree).
ObserverLike = Union[str, int]

class NoteWarning(UserWarning):
    """What ``bandlight`` prints as ``note: ...``: an assumption made about the input."""

# --- spectra ---------------------------------------------------------------

class Spectrum:
    """A spectrum sampled on a regular wavelength grid (nm), with a name."""

    name: str
    def __init__(self, wavelengths: npt.ArrayLike, values: npt.ArrayLike, name: str = "") -> None: ...
    @property
    def wavelengths(self) -> FloatArray: ...
    @property
    def values(self) -> FloatArray: ...
    @property
    def start(self) -> float: ...
    @property
    def step(self) -> float: ...
    @property
    def end(self) -> float: ...
    @overload
    def __call__(self, wavelength: float) -> float: ...
    @overload
    def __call__(self, wavelength: Union[npt.NDArray[Any], Sequence[float]]) -> FloatArray: ...
    def resampled(self, start: float, step: float, count: int) -> Spectrum: ...
    def extended(self, start: float, end: float) -> Spectrum: ...
    def sum(self) -> float: ...
    def integrate(self, start: float, end: float) -> float: ...
    def band_means(self, bands: BandsLike = None, rule: str = "lecture") -> FloatArray: ...
    @overload
    def __mul__(self, other: float) -> Spectrum: ...
    @overload
    def __mul__(self, other: Spectrum) -> Spectrum: ...
    def __rmul__(self, other: float) -> Spectrum: ...
    @overload
    def __truediv__(self, other: float) -> Spectrum: ...
    @overload
    def __truediv__(self, other: Spectrum) -> Spectrum: ...
    @overload
    def __add__(self, other: float) -> Spectrum: ...
    @overload
    def __add__(self, other: Spectrum) -> Spectrum: ...
    def __radd__(self, other: float) -> Spectrum: ...
    @overload
    def __sub__(self, other: float) -> Spectrum: ...
    @overload
    def __sub__(self, other: Spectrum) -> Spectrum: ...
    def __len__(self) -> int: ...

def illuminant(name_or_file: StrPath) -> Spectrum: ...
def illuminant_names() -> List[str]: ...
def daylight(cct: float) -> Spectrum: ...
def planckian(kelvin: float, start: float = 300.0, step: float = 5.0, count: int = 107) -> Spectrum: ...
def daylight_basis() -> Tuple[Spectrum, Spectrum, Spectrum]: ...
def cmf(observer: ObserverLike = "1931", set: str = "xyz") -> Tuple[Spectrum, Spectrum, Spectrum]: ...
def reflectances(name_or_file: StrPath = "TCS") -> List[Spectrum]: ...
def reflectance_set(name: str) -> List[Spectrum]: ...
def read_spectra(path: StrPath) -> List[Spectrum]: ...
def parse_spectra(text: str, source: str = "<string>") -> List[Spectrum]: ...

# --- colorimetry -------------------------------------------------------------

class CriResult(TypedDict):
    illuminant: str
    cct_K: float
    duv: float
    Ra: float
    R: List[float]
    outside_duv_tolerance: bool

class RgbSpaceInfo(TypedDict):
    name: str
    display_name: str
    description: str
    primaries: Tuple[Tuple[float, float], Tuple[float, float], Tuple[float, float]]
    white: Tuple[float, float]

@overload
def xyz(illuminant: LightLike, reflectance: None = None, *, observer: ObserverLike = "1931") -> FloatArray: ...
@overload
def xyz(illuminant: LightLike, reflectance: RemittancesLike, *, observer: ObserverLike = "1931") -> FloatArray: ...

class XyzIntegrator:
    """Precomputed weights: a remittance's XYZ (white Y = 100) as three dot products."""

    @property
    def illuminant(self) -> str: ...
    def __init__(self, illuminant: LightLike, observer: ObserverLike = "1931") -> None: ...
    @property
    def wavelengths(self) -> FloatArray: ...
    @property
    def weights(self) -> FloatArray: ...
    @property
    def white(self) -> FloatArray: ...
    def __call__(self, remittances: Union[RemittancesLike, npt.ArrayLike]) -> FloatArray: ...

def xyz_to_xyy(xyz: npt.ArrayLike) -> FloatArray: ...
def xyy_to_xyz(xyy: npt.ArrayLike) -> FloatArray: ...
def xyz_to_lab(xyz: npt.ArrayLike, white: npt.ArrayLike) -> FloatArray: ...
def lab_to_xyz(lab: npt.ArrayLike, white: npt.ArrayLike) -> FloatArray: ...
def delta_e76(lab1: npt.ArrayLike, lab2: npt.ArrayLike) -> Union[float, FloatArray]: ...
def delta_e2000(lab1: npt.ArrayLike, lab2: npt.ArrayLike, kL: float = 1.0, kC: float = 1.0,
                kH: float = 1.0) -> Union[float, FloatArray]: ...
def cct(xyz: npt.ArrayLike) -> Tuple[Union[float, FloatArray], Union[float, FloatArray]]: ...
def cri(illuminant: LightLike) -> CriResult: ...

def wall(emitters: Union[Mapping[str, StrPath], Sequence[str], str], camera: StrPath, white_balances: Union[Sequence[str], str], *, content_space: str, out: StrPath, training: Optional[StrPath] = None, test_set: Optional[StrPath] = None) -> Dict[str, Any]: ...

@dataclass(frozen=True)
class Quality:
    light: str
    cct: float
    duv: float
    cri: Optional[Dict[str, Any]]
    cie2017: Optional[Dict[str, Any]]
    tm30: Optional[Dict[str, Any]]
    ssi: Optional[Dict[str, Any]]
    tlci: Optional[Dict[str, Any]]
    tlmf: Optional[Dict[str, Any]]
    warnings: Tuple[str, ...]
    def __init__(self, light: str, cct: float, duv: float, cri: Optional[Dict[str, Any]], cie2017: Optional[Dict[str, Any]], tm30: Optional[Dict[str, Any]], ssi: Optional[Dict[str, Any]], tlci: Optional[Dict[str, Any]], tlmf: Optional[Dict[str, Any]], warnings: Tuple[str, ...]) -> None: ...

@overload
def quality(light: LightLike, reference: Optional[LightLike] = None, *, threads: int = 0) -> Quality: ...
@overload
def quality(light: Sequence[LightLike], reference: Optional[LightLike] = None, *, threads: int = 0) -> List[Quality]: ...
def adaptation_matrix(src_white: npt.ArrayLike, dst_white: npt.ArrayLike, method: str = "bradford") -> FloatArray: ...
def rgb_spaces() -> List[RgbSpaceInfo]: ...
def rgb_to_xyz_matrix(space: str = "acescg") -> FloatArray: ...

# --- the band model ------------------------------------------------------------

class BandSet:
    """An ordered set of wavelength bands [min_nm, max_nm)."""

    @overload
    def __init__(self, edges: str) -> None: ...
    @overload
    def __init__(self, edges: Sequence[float]) -> None: ...
    @staticmethod
    def lecture() -> BandSet: ...
    @staticmethod
    def equal(n: int, min_nm: float = 400.0, max_nm: float = 700.0) -> BandSet: ...
    @staticmethod
    def named(bands: Sequence[Tuple[str, float, float]]) -> BandSet: ...
    @property
    def names(self) -> List[str]: ...
    @property
    def bands(self) -> List[Tuple[str, float, float]]: ...
    def describe(self) -> str: ...
    def __len__(self) -> int: ...

MAX_BAND_CONDITION: float

def illuminant_bands(illuminant: LightLike, bands: BandsLike = None, *, rule: str = "lecture") -> FloatArray: ...
def remittance_bands(reflectance: RemittancesLike, bands: BandsLike = None, *, rule: str = "lecture") -> FloatArray: ...
def matching_band_matrix(bands: BandsLike = None, *, set: str = "xyz", observer: ObserverLike = "1931",
                         rule: str = "lecture") -> FloatArray: ...
def band_to_colour_matrix(bands: BandsLike = None, *, set: str = "xyz", observer: ObserverLike = "1931",
                          rule: str = "lecture") -> Tuple[FloatArray, FloatArray, float]: ...
def working_to_band_matrix(bands: BandsLike = None, *, working_space: str = "acescg",
                           observer: ObserverLike = "1931") -> FloatArray: ...
def band_to_working_matrix(bands: BandsLike = None, *, working_space: str = "acescg",
                           observer: ObserverLike = "1931") -> FloatArray: ...
def condition_number(matrix: npt.ArrayLike) -> float: ...
def tables(bands: BandsLike = None, *, observer: ObserverLike = "1931", rule: str = "lecture") -> Dict[str, Any]: ...

# --- transforms ------------------------------------------------------------------

def methods() -> List[str]: ...
def linear_methods() -> List[str]: ...
def describe_method(method: str) -> str: ...
def method_name(method: str) -> str: ...
def look_name(method: str, src: str, dst: str) -> str: ...
def illuminant_change(src: LightLike, dst: LightLike, method: str = "bradford", *,
                      working_space: str = "acescg", observer: ObserverLike = "1931",
                      lut_size: int = 33,
                      training: Optional[RemittancesLike] = None,
                      plates: str = "balanced", adaptation: str = "cat02",
                      camera: Optional[StrPath] = None, camera_idt: str = "D55") -> OCIO.GroupTransform: ...
def illuminant_change_matrix(src: LightLike, dst: LightLike, method: str = "bradford", *,
                             working_space: str = "acescg", observer: ObserverLike = "1931",
                             training: Optional[RemittancesLike] = None,
                             plates: str = "balanced", adaptation: str = "cat02") -> FloatArray: ...
def band_space(bands: BandsLike = None, *, working_space: str = "acescg",
               observer: ObserverLike = "1931") -> OCIO.GroupTransform: ...
def material_tint(remittance: Union[Sequence[float], Spectrum], bands: BandsLike = None, *,
                  working_space: str = "acescg", observer: ObserverLike = "1931") -> OCIO.GroupTransform: ...
def measure_matrix(processor: OCIO.Processor) -> FloatArray: ...

class Relighter:
    """An illuminant change ready to apply to pixels in memory (the C++ Relighter)."""

    @property
    def src(self) -> str: ...
    @property
    def dst(self) -> str: ...
    @property
    def method(self) -> str: ...
    @property
    def working_space(self) -> str: ...
    @property
    def plates(self) -> str: ...
    def __init__(self, src: LightLike, dst: LightLike, method: str = "bradford", *,
                 working_space: str = "acescg", observer: ObserverLike = "1931",
                 training: Optional[RemittancesLike] = None,
                 plates: str = "balanced", adaptation: str = "cat02",
                 camera: Optional[StrPath] = None, camera_idt: str = "D55") -> None: ...
    def apply(self, image: npt.ArrayLike, *, threads: int = 0,
              out: Optional[Float32Array] = None) -> Float32Array: ...
    def __call__(self, image: npt.ArrayLike, *, threads: int = 0,
                 out: Optional[Float32Array] = None) -> Float32Array: ...
    @property
    def is_linear(self) -> bool: ...
    @property
    def matrix(self) -> FloatArray: ...

def relight(image: npt.ArrayLike, src: LightLike, dst: LightLike, method: str = "bradford", *,
            working_space: str = "acescg", observer: ObserverLike = "1931",
            training: Optional[RemittancesLike] = None, threads: int = 0,
            out: Optional[Float32Array] = None,
            plates: str = "balanced", adaptation: str = "cat02",
            camera: Optional[StrPath] = None, camera_idt: str = "D55") -> Float32Array: ...
def relight_light_groups(groups: Mapping[str, npt.ArrayLike],
                         changes: Mapping[str, Union[Tuple[LightLike, LightLike],
                                                     Tuple[LightLike, LightLike, str]]], *,
                         beauty: Optional[npt.ArrayLike] = None, method: str = "bradford",
                         working_space: str = "acescg", observer: ObserverLike = "1931",
                         training: Optional[RemittancesLike] = None, plates: str = "lit",
                         adaptation: str = "cat02", camera: Optional[StrPath] = None,
                         camera_idt: str = "D55", threads: int = 0) -> Dict[str, Any]: ...

# --- jobs ------------------------------------------------------------------------

class LutResult(TypedDict):
    lut: str
    shaper: Optional[str]
    lattice: bool
    output_encoded: bool
    shaper_description: Optional[str]
    encoding: str
    encoding_description: str

#: A row of the accuracy report ("from" is a keyword, hence this form).
AccuracyRow = TypedDict("AccuracyRow", {
    "method": str, "from": str, "to": str, "set": str, "plates": str, "camera": str,
    "exposure": float, "shipped": bool, "mean": float, "p95": float, "max": float,
    "worst_sample": str,
})


class AccuracyCamera(TypedDict):
    name: str
    file: str
    idt_light: str


class AccuracyCost(TypedDict):
    method: str
    form: str
    ns_per_pixel: float
    mpixel_per_s: float
    threads: int


class AccuracySetupCost(TypedDict):
    what: str
    seconds: float


class AccuracyDocument(TypedDict):
    camera: Optional[AccuracyCamera]
    rows: List[AccuracyRow]
    cross_validation: List[AccuracyRow]
    floor: List[AccuracyRow]
    cost: List[AccuracyCost]
    setup_cost: List[AccuracySetupCost]


class ApplyResult(TypedDict):
    applied: str
    frames: int
    skipped: int
    failed: List[Tuple[int, str]]
    seconds: float

def config(out: Optional[StrPath] = None, *, working_space: Optional[str] = None,
           illuminants: Union[str, Sequence[LightLike]] = ("A", "C", "D65", "F2", "F11"),
           methods: Union[str, Sequence[str], None] = None, observer: ObserverLike = "1931",
           lut_size: int = 65, base: Union[StrPath, OCIO.Config, None] = None,
           base_paths: str = "relative",
           plates: str = "balanced", adaptation: str = "cat02",
           camera: Optional[StrPath] = None, camera_idt: str = "D55") -> OCIO.Config: ...
def identify_scene_linear(config: Union[StrPath, OCIO.Config]) -> Tuple[str, str]: ...
def lut(path: StrPath, src: LightLike, dst: LightLike, method: str = "bradford", *,
        format: Optional[str] = None, size: Optional[int] = None, shaper: str = "log2",
        encoding: str = "linear", working_space: str = "acescg", observer: ObserverLike = "1931",
        training: Optional[RemittancesLike] = None,
        plates: str = "balanced", adaptation: str = "cat02",
        camera: Optional[StrPath] = None, camera_idt: str = "D55") -> LutResult: ...
def accuracy(illuminants: Union[str, Sequence[LightLike], None] = None,
             methods: Union[str, Sequence[str], None] = None, *,
             reflectances: Union[StrPath, Sequence[StrPath], Mapping[str, RemittancesLike], None] = None,
             default_sets: bool = True, working_space: str = "acescg",
             observer: ObserverLike = "1931", exposures: Optional[Sequence[float]] = None,
             lut_size: int = 65, ideal_only: bool = False, cross_validation: bool = True,
             floor: bool = True, cost: bool = True,
             progress: Optional[Callable[[float], None]] = None,
             plates: str = "both", adaptation: str = "cat02",
             camera: Optional[StrPath] = None, camera_idt: str = "D55",
             json: Optional[StrPath] = None,
             plot: Optional[StrPath] = None) -> AccuracyDocument: ...
def idt(camera: Optional[StrPath] = None, lights: Union[str, Sequence[StrPath], None] = None, *,
        working_space: str = "aces2065-1", adaptation: str = "cat02",
        observer: ObserverLike = "1931", training: Optional[StrPath] = None,
        test_set: StrPath = "TCS", interpolate: Union[str, Sequence[StrPath], None] = None,
        as_shot_neutral: Optional[Sequence[float]] = None,
        as_shot_light: Optional[Union[str, Sequence[str]]] = None, chart_rgb: Optional[StrPath] = None,
        chart: Optional[StrPath] = None, light: Optional[StrPath] = None, rootpoly: int = 0,
        json: Optional[StrPath] = None, config: Optional[StrPath] = None,
        base: Optional[StrPath] = None, out: Optional[StrPath] = None,
        base_space: Optional[str] = None) -> Dict[str, Any]: ...
def frame_set(text: str) -> List[int]: ...
def apply(input: StrPath, output: StrPath, *,
          frames: Optional[Union[str, range, Sequence[int]]] = None, client: Any = None,
          **options: Any) -> ApplyResult: ...
def _apply(input: StrPath, output: StrPath, *, frames: Optional[str] = None,
          look: Optional[str] = None, config: Optional[StrPath] = None,
          colorspace: Optional[str] = None, src: Optional[LightLike] = None,
          dst: Optional[LightLike] = None, method: Optional[str] = None,
          working_space: Optional[str] = None, observer: ObserverLike = "1931",
          training: Optional[RemittancesLike] = None,
          plates: Optional[str] = None, adaptation: Optional[str] = None,
          camera: Optional[StrPath] = None, camera_idt: Optional[str] = None,
          threads: int = 0, skip_existing: bool = False,
          keep_going: bool = False,
          light_groups: Optional[Mapping[str, Tuple[LightLike, LightLike]]] = None,
          light_group_layers: Optional[Mapping[str, str]] = None,
          light_group_beauty: Optional[str] = None) -> ApplyResult: ...
@overload
def render(scene: Optional[StrPath] = None, *, text: Optional[str] = None, source: str = "<scene>",
           mode: Optional[str] = None, threads: int = 0, unplanned: bool = False,
           out: None = None, spectra: bool = False, compare: bool = False,
           preview: Union[bool, StrPath] = True, light_groups: bool = False) -> Float32Array: ...
@overload
def render(scene: Optional[StrPath] = None, *, text: Optional[str] = None, source: str = "<scene>",
           mode: Optional[str] = None, threads: int = 0, unplanned: bool = False,
           out: StrPath, spectra: bool = False, compare: bool = False,
           preview: Union[bool, StrPath] = True, light_groups: bool = False) -> Dict[str, Any]: ...
def explain_scene(scene: Optional[StrPath] = None, *, text: Optional[str] = None,
                  source: str = "<scene>", mode: Optional[str] = None,
                  unplanned: bool = False) -> str: ...
def read_spectral_image(path: StrPath, *,
                        channels: Union[Mapping[str, float], StrPath, None] = None,
                        kind: str = "emissive",
                        sampling: str = "auto") -> Tuple[FloatArray, Float32Array, str, str]: ...
def spectral_to_rgb(spectra: npt.ArrayLike, wavelengths: npt.ArrayLike, *,
                    kind: str = "emissive", src: Optional[LightLike] = None,
                    dst: Optional[LightLike] = None, working_space: str = "acescg",
                    plates: str = "balanced", adaptation: str = "cat02",
                    observer: ObserverLike = "1931", sampling: str = "auto",
                    threads: int = 0) -> Float32Array: ...
def spectral(input: StrPath, output: StrPath, *, frames: Optional[str] = None,
             src: Optional[LightLike] = None, dst: Optional[LightLike] = None,
             working_space: str = "acescg", plates: Optional[str] = None,
             adaptation: str = "cat02", observer: ObserverLike = "1931",
             channels: Union[Mapping[str, float], StrPath, None] = None,
             kind: str = "emissive", sampling: str = "auto", threads: int = 0,
             skip_existing: bool = False, keep_going: bool = False,
             light_groups: Optional[Mapping[str, Tuple[LightLike, LightLike]]] = None) -> Dict[str, Any]: ...
