"""Type stubs of shadow_aliasing (the closed forms broadcast over every float argument)."""
from typing import List, Literal, Optional, Sequence, Tuple, TypedDict, Union, final, overload

import numpy as np
import numpy.typing as npt

ArrayLike = npt.ArrayLike
F64 = Union[np.float64, npt.NDArray[np.float64]]
Vec3 = Union[Sequence[float], npt.NDArray[np.floating]]
ClipDepth = Literal["neg_one_to_one", "zero_to_one", "reversed"]
# ``out=``: an array of the result's shape and dtype that receives the result (and is returned).
OutArray = Optional[npt.NDArray[np.floating]]
# ``dtype=``: numpy.float64 (the default) or numpy.float32 for matrices.
DType = Union[type, "np.dtype[np.floating]", Literal["float64", "float32"], None]


class BevySplits(TypedDict):
    """Bevy's ``CascadeShadowConfigBuilder`` fields (``frame(..., bevy=...)``)."""
    num_cascades: int
    minimum_distance: float
    maximum_distance: float
    first_cascade_far_bound: float
    overlap_proportion: float


class FrameResult(TypedDict):
    """``frame``'s maps, one per entry along the first axis (m maps)."""
    focus: Literal["body", "empty", "flat", "edge_on", "zero_depth"]
    light: Literal["general", "sun_straight_down", "parallel_to_view"]
    light_dir_eye: npt.NDArray[np.float64]
    world_to_clip: npt.NDArray[np.floating]
    eye_to_clip: npt.NDArray[np.floating]
    n_prime: npt.NDArray[np.float64]
    depth: npt.NDArray[np.float64]
    split: npt.NDArray[np.float64]
    blend: npt.NDArray[np.float64]
    texel_world: npt.NDArray[np.float64]
    max_mx: npt.NDArray[np.float64]
    max_mz: npt.NDArray[np.float64]
    storage_factor: npt.NDArray[np.float64]
    max_error_pixels: npt.NDArray[np.float64]
    normal_offset: npt.NDArray[np.float64]
    slope_scaled_depth: npt.NDArray[np.float64]
    constant_depth: npt.NDArray[np.float64]
    texel_extent: npt.NDArray[np.float64]
    slot: npt.NDArray[np.int64]
    resolution: npt.NDArray[np.int64]
    map_focus: List[str]
    face: List[Optional[str]]
    clipmap_level: List[Optional[int]]
    body: List[npt.NDArray[np.float64]]
    casters_volume: List[npt.NDArray[np.float64]]
    receivers_volume: List[npt.NDArray[np.float64]]


class ControllerFrame(TypedDict):
    """``Controller.frame``'s decision and maps (m maps)."""
    scheme: str
    frame_kwargs: dict[str, object]
    warp_args: Optional[List[str]]
    resolution: int
    resolutions: npt.NDArray[np.int64]
    max_error_pixels: float
    texels: int
    meets_target: bool
    within_budget: bool
    switched: bool
    cut: bool
    unchanged: npt.NDArray[np.bool_]
    maps: FrameResult


@final
class Controller:
    """The error-budget controller: the cheapest set-up (a scheme, one square resolution shared
    by its maps, or each map's own with ``shared_resolution=False``) whose measured largest
    error meets ``max_error`` (within ``budget_texels``), else the least error that fits; kept
    from frame to frame. Options are keywords; the defaults are the crate's
    ``ControllerOptions::new``."""
    def __new__(cls, *, max_error: Optional[float] = ..., budget_texels: Optional[int] = ...,
                 max_maps: Optional[int] = ...,
                 rounding: Union[Literal["whole", "power_of_two"], int, None] = ...,
                 max_resolution: Optional[int] = ..., shared_resolution: bool = ...,
                 candidates: Optional[Sequence[str]] = ..., patience: Optional[int] = ...,
                 margin: Optional[float] = ...,
                 neighbour_every: Optional[int] = ..., retry_every: Optional[int] = ...,
                 cut_move: Optional[float] = ..., cut_turn: Optional[float] = ...,
                 cut_light: Optional[float] = ...) -> "Controller": ...
    def frame(self, view: ArrayLike, near: float, far: float, half_fov: float, light_dir: Vec3, *,
              image_height: int, aspect: float = ..., receivers: Optional[ArrayLike] = ...,
              casters: Optional[ArrayLike] = ..., depth_range: Optional[ArrayLike] = ...,
              depth_clamp: bool = ..., pcf_radius: float = ..., clip_depth: ClipDepth = ...,
              dtype: DType = ...) -> ControllerFrame:
        """This frame's set-up and maps; every candidate searched on a cut."""
    def cut(self) -> None:
        """Makes the next frame a cut (every candidate searched)."""
    def error_lens(self, points: ArrayLike, normals: ArrayLike, *,
                   map_index: Optional[ArrayLike] = ...,
                   fill: float = ...) -> npt.NDArray[np.float64]:
        """(...) the last frame's map texel in pixels on the surfaces at world ``points`` (..., 3)
        with ``normals`` (..., 3), the projection factor included (``FrameMap::error_lens_at``)."""

WARP_RULES: list[str]
__version__: str
__all__ = [
    "WARP_RULES",
    "Controller",
    "allocate_texels",
    "cascades",
    "critical_resolution",
    "distribution_g",
    "error_image",
    "eta_from_n_prime",
    "faces",
    "frame",
    "frustum_max",
    "gamma_lim",
    "generalized_n_prime",
    "max_mx",
    "max_mz",
    "mx",
    "mz",
    "n_prime_for",
    "n_prime_from_eta",
    "n_prime_lispsm",
    "plan",
    "plan_clipmap",
    "point_error",
    "scheme_storage_factor",
    "storage_factor",
    "subdivided_max_error",
    "sweep",
    "sweep_angles",
    "tilted_mz",
    "tsm",
    "tsm_eta",
    "warp",
    "z_partition",
    "zhang_ep",
    "zhang_ep_local",
    "zhang_eq",
    "zhang_eq_local",
]

def mx(near: ArrayLike, far: ArrayLike, n_prime: ArrayLike, z: ArrayLike,
       res_image: Optional[ArrayLike] = ..., res_s: Optional[ArrayLike] = ..., *, out: OutArray = ...) -> F64:
    """m_x = (res_image/res_s) f (n′ + z − n)/(z (n′ + f − n)) (Lloyd 2006 Eq 7)."""
def mz(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, n_prime: ArrayLike, z: ArrayLike,
       res_image: Optional[ArrayLike] = ..., res_t: Optional[ArrayLike] = ..., *, out: OutArray = ...) -> F64:
    """m_z = (res_image/res_t) (f − n)/(2 tan θ) (n′ + z − n)²/(z n′ (n′ + f − n)) (Lloyd 2006 Eq 8)."""
def max_mx(near: ArrayLike, far: ArrayLike, n_prime: ArrayLike,
           res_image: Optional[ArrayLike] = ..., res_s: Optional[ArrayLike] = ..., *, out: OutArray = ...) -> F64:
    """M_x = (res_image/res_s) f n′/(n (n′ + f − n)), f/n for n′ = ∞: m_x at z = near (Lloyd 2006 Eq 9)."""
def max_mz(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, n_prime: ArrayLike,
           res_image: Optional[ArrayLike] = ..., res_t: Optional[ArrayLike] = ..., *, out: OutArray = ...) -> F64:
    """M_z = (res_image/res_t) (f − n)/(2 tan θ) · {(n′ + f − n)/(f n′) for n′ ≤ n + √(f n);
    n′/((n′ + f − n) n) above; 1/n for n′ = ∞} (Lloyd 2006 Eq 10)."""
def storage_factor(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, n_prime: ArrayLike, *, out: OutArray = ...) -> F64:
    """S̄ = (f/n − 1)/(2 tan θ) · {1; n′² f/(n (n′ + f − n)²); f/n} (Lloyd 2006 Eq 12)."""
def critical_resolution(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, n_prime: ArrayLike,
                        budget: ArrayLike, res_image: Optional[ArrayLike] = ..., *, out: OutArray = ...) -> npt.NDArray[np.float64]:
    """[res_s, res_t] (last axis) with res_s/res_t = M_x/M_z, res_s res_t = budget (Lloyd 2006 Eq 13, 14)."""
def n_prime_lispsm(near: ArrayLike, far: ArrayLike, *, out: OutArray = ...) -> F64:
    """n′ = n + √(f n) (Lloyd 2006 §4.1)."""
def n_prime_from_eta(near: ArrayLike, far: ArrayLike, eta: ArrayLike, *, out: OutArray = ...) -> F64:
    """n′ = n (√α + 1 − η (α − 1))/(η + 1) for −1 ≤ η ≤ 0, n (√α + 1)/(η √α + 1) for 0 < η ≤ 1,
    α = f/n (Lloyd 2006 Eq 11); inf for η = −1."""
def eta_from_n_prime(near: ArrayLike, far: ArrayLike, n_prime: ArrayLike, *, out: OutArray = ...) -> F64:
    """η = (√α + 1 − ν)/(ν + α − 1) for ν ≥ 1 + √α, (√α + 1 − ν)/(ν √α) below, ν = n′/n, α = f/n;
    −1 for n′ = ∞ (Lloyd 2006 App. B, the inverse of Eq 11)."""
def distribution_g(alpha: ArrayLike, n_warp: ArrayLike, z: ArrayLike, *, out: OutArray = ...) -> F64:
    """g(z) = (z − 1 + n)²/(z n (n + α − 1)) (Lloyd 2005 Eq 3)."""
def subdivided_max_error(alpha: ArrayLike, k: ArrayLike, eta: ArrayLike, half_fov: ArrayLike,
                         res_image: Optional[ArrayLike] = ..., res_s: Optional[ArrayLike] = ..., *, out: OutArray = ...) -> F64:
    """m_max = k (res_image/res_s)/(2 tan θ) · (α^(1/k) − 1)/α^(1/2k) · (1 + |ξ| (α^(1/2k) − 1)),
    ξ = eta, k whole ≥ 1 (Lloyd 2005 Eq 7)."""
def allocate_texels(errors: ArrayLike, total: float, *, out: OutArray = ...) -> npt.NDArray[np.float64]:
    """r_si = total e_i/Σ e_j (Lloyd 2005 Eq 6)."""
def z_partition(near: ArrayLike, far: ArrayLike, k: int,
                scheme: Literal["self_similar", "uniform", "practical", "adaptive"],
                lambda_: Optional[ArrayLike] = ..., light_angle: Optional[ArrayLike] = ...,
                ratio: Optional[ArrayLike] = ..., *, out: OutArray = ...) -> npt.NDArray[np.float64]:
    """The k + 1 split planes (last axis): z_i = n (f/n)^(i/k) ("self_similar", Lloyd 2006 Eq 15, 16),
    n + (f − n) i/k ("uniform"), λ of the first plus 1 − λ of the second ("practical"), Barroso
    Eq 19 ("adaptive")."""
def scheme_storage_factor(scheme: Literal["zp", "zp_w", "fp_zp_w", "optimal"],
                          light: Literal["overhead", "behind"], near: ArrayLike, far: ArrayLike,
                          half_fov: ArrayLike, k: ArrayLike, *, out: OutArray = ...) -> F64:
    """S̄ of a partitioning scheme summed over its maps (Lloyd 2006 Eq 17–21, App. C), e.g. ZP+W
    overhead S̄ = k (α^(1/k) − 1)/(2 tan θ) (Eq 18), optimal S̄ = ln α/(2 tan θ) (App. C)."""
def tilted_mz(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, n_prime: ArrayLike,
              light_angle: ArrayLike, z: ArrayLike, res_image: Optional[ArrayLike] = ...,
              res_t: Optional[ArrayLike] = ..., *, out: OutArray = ...) -> F64:
    """m_z = (res_image/res_t) (f′ − n′) ψ²/(2 tan θ n′ f′ z sin γ), ψ the warp depth of the point
    (Barroso Eq 10–12); μ/(2 tan θ z sin γ) unwarped."""
def generalized_n_prime(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, light_angle: ArrayLike,
                        falloff: Literal["barroso", "zhang"], *, out: OutArray = ...) -> F64:
    """Barroso's generalised n′: n′₁(γ) for γ ≥ γ_lim, else n′₁(γ_lim)/r(γ) with r of Eq 18
    ("barroso") or Eq 17 ("zhang") (Barroso Eq 13–18); inf at γ = 0."""
def gamma_lim(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, *, out: OutArray = ...) -> F64:
    """γ_lim = atan((f + n) tan θ/(f − n)) (Barroso Eq 15)."""
def tsm_eta(lambda_: ArrayLike, delta_prime: ArrayLike, xi: ArrayLike, *, out: OutArray = ...) -> F64:
    """η = λ δ′ (1 + ξ)/(λ (1 − ξ) − 2 δ′) (Martin–Tan §6.2)."""
def zhang_eq(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, lambda_: ArrayLike,
             light_angle: ArrayLike, y: ArrayLike, z: ArrayLike, *, out: OutArray = ...) -> F64:
    """E_q = 2 tan φ_w z_w/(tan φ z) = F_q (z + G)/z, 2 f/z for λ = ∞ (Zhang Eq 13, Appendix)."""
def zhang_ep(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, lambda_: ArrayLike,
             light_angle: ArrayLike, y: ArrayLike, z: ArrayLike, *, out: OutArray = ...) -> F64:
    """E_p = μ z_w²/(tan φ (λ + μ) λ z) = F_p (z + G)²/z, μ/(tan φ z) for λ = ∞ (Zhang Eq 14, Appendix)."""
def zhang_eq_local(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, lambda_: ArrayLike, z: ArrayLike, *, out: OutArray = ...) -> F64:
    """E_q = 2 f (z − n + λ)/((f − n + λ) z) for λ ≥ n, 2 n (z − n + λ)/(λ z) for λ < n,
    2 f / z for λ = ∞ (Zhang Eq 8)."""
def zhang_ep_local(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, lambda_: ArrayLike, z: ArrayLike, *, out: OutArray = ...) -> F64:
    """E_p = (f − n)(z − n + λ)²/((f − n + λ) λ tan φ z) (Zhang Eq 9)."""

def warp(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, light_dir: ArrayLike,
         rule: str = ..., *, eta: Optional[float] = ..., focus: Optional[float] = ...,
         near_hint: Optional[float] = ..., far_hint: Optional[float] = ...,
         shadow_distance: Optional[float] = ..., clip_depth: ClipDepth = ..., aspect: float = ...,
         dtype: DType = ..., out: OutArray = ...) -> npt.NDArray[np.floating]:
    """The (4, 4) shadow matrix of one map, n′ by the named rule (Lloyd 2006 §4); (..., 4, 4)
    for stacks (near, far, half_fov and light directions (..., 3) broadcast)."""
def n_prime_for(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, light_dir: ArrayLike,
                rule: str = ..., *, eta: Optional[float] = ..., focus: Optional[float] = ...,
                near_hint: Optional[float] = ..., far_hint: Optional[float] = ...,
                shadow_distance: Optional[float] = ..., aspect: float = ...,
                out: OutArray = ...) -> F64:
    """The n′ the rule chooses (inf: unwarped); (...,) for stacks (as ``warp``)."""
def cascades(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, light_dir: ArrayLike, k: int,
             partition: Literal["self_similar", "log", "uniform", "practical", "adaptive"] = ...,
             rule: str = ..., *, lambda_: Optional[float] = ..., overlap: float = ...,
             eta: Optional[float] = ..., focus: Optional[float] = ..., clip_depth: ClipDepth = ...,
             aspect: float = ..., dtype: DType = ...,
             out: OutArray = ...) -> npt.NDArray[np.floating]:
    """(k, 4, 4) z-partition matrices, near to far; (..., k, 4, 4) for stacks (as ``warp``)."""
def faces(near: float, far: float, half_fov: float, light_dir: Vec3, k: int = ...,
          warp: Literal["uniform", "psm", "lispsm"] = ..., *, clip_depth: ClipDepth = ...,
          aspect: float = ..., dtype: DType = ...) -> Tuple[npt.NDArray[np.floating], list[str]]:
    """(m, 4, 4) face-partition matrices and their faces (Lloyd 2006 §5.1)."""
def tsm(near: ArrayLike, far: ArrayLike, half_fov: ArrayLike, light_dir: ArrayLike,
        focus: Optional[float] = ..., *, xi: Optional[float] = ..., iterative: Optional[int] = ...,
        clip_depth: ClipDepth = ..., aspect: float = ..., dtype: DType = ...,
        out: OutArray = ...) -> npt.NDArray[np.floating]:
    """The (4, 4) trapezoidal shadow matrix (Martin & Tan 2004); (..., 4, 4) for stacks."""
def frustum_max(matrix: ArrayLike, light_dir: ArrayLike, near: ArrayLike, far: ArrayLike,
                half_fov: ArrayLike, *, aspect: float = ...,
                out: OutArray = ...) -> npt.NDArray[np.float64]:
    """[M_x, M_z, S̄] (last axis) of (..., 4, 4) matrices, measured at the frustum's vertices;
    matrices, light directions (..., 3), near, far and half_fov broadcast."""
def point_error(matrix: ArrayLike, light_dir: ArrayLike, point: ArrayLike, near: ArrayLike,
                far: ArrayLike, half_fov: ArrayLike, *, res_image: float = ..., res_s: float = ...,
                res_t: float = ..., aspect: float = ...,
                out: OutArray = ...) -> npt.NDArray[np.float64]:
    """[m_x, m_z] (last axis) at (..., 3) eye-space points; every argument but the
    resolutions broadcasts."""
@overload
def error_image(depth: ArrayLike, projection: ArrayLike, view: ArrayLike,
                shadow_matrix: ArrayLike, *, map_resolution: int = ...,
                map_resolutions: Optional[ArrayLike] = ...,
                clip_depth: ClipDepth = ..., normals: Optional[ArrayLike] = ...,
                map_index: Optional[ArrayLike] = ..., background: Optional[float] = ...,
                fill: float = ..., return_jacobian: Literal[False] = ...,
                out: OutArray = ...) -> npt.NDArray[np.float64]:
    """(H, W) predicted error, pixels per texel (1/σ_min of the exact footprint J: the error
    lens, as ``Controller.error_lens``), of every pixel of a depth buffer (H, W); ``fill`` where
    there is no prediction, inf edge-on to the light."""
@overload
def error_image(depth: ArrayLike, projection: ArrayLike, view: ArrayLike,
                shadow_matrix: ArrayLike, *, map_resolution: int = ...,
                map_resolutions: Optional[ArrayLike] = ...,
                clip_depth: ClipDepth = ..., normals: Optional[ArrayLike] = ...,
                map_index: Optional[ArrayLike] = ..., background: Optional[float] = ...,
                fill: float = ..., return_jacobian: Literal[True],
                out: OutArray = ...) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """``(error (H, W), jacobian (H, W, 2, 2))``."""
def frame(view: ArrayLike, near: float, far: float, half_fov: float, light_dir: Vec3, *,
          aspect: float = ..., receivers: Optional[ArrayLike] = ..., casters: Optional[ArrayLike] = ...,
          depth_range: Optional[ArrayLike] = ..., depth_clamp: bool = ..., measure: bool = ...,
          map_resolution: int = ..., image_height: int = ...,
          map_resolutions: Optional[ArrayLike] = ..., pcf_radius: float = ...,
          scheme: Literal["single", "cascades", "stable", "tsm", "faces", "clipmap"] = ...,
          rule: Optional[str] = ..., k: Optional[int] = ...,
          partition: Optional[Literal["self_similar", "log", "uniform", "practical", "adaptive",
                                      "equal_error"]] = ...,
          splits: Optional[ArrayLike] = ..., fractions: Optional[ArrayLike] = ...,
          bevy: Optional[BevySplits] = ..., lambda_: Optional[float] = ...,
          overlap: Optional[float] = ..., eta: Optional[float] = ..., focus: Optional[float] = ...,
          near_hint: Optional[float] = ..., far_hint: Optional[float] = ...,
          shadow_distance: Optional[float] = ..., xi: Optional[float] = ...,
          iterative: Optional[int] = ..., lod_bias: Optional[float] = ...,
          levels: Optional[ArrayLike] = ..., level_unit: Optional[float] = ...,
          page_texels: Optional[int] = ..., centre: Literal["rule", "eye", "nearest_vertex"] = ...,
          clip_depth: ClipDepth = ...,
          dtype: DType = ...) -> FrameResult:
    """The shadow maps of one frame in world space, fitted to the scene (the crate's frame API)."""
def plan(view: ArrayLike, near: float, far: float, half_fov: float, light_dir: Vec3, *,
         image_height: int, max_error: Optional[float] = ..., budget_texels: Optional[int] = ...,
         max_maps: Optional[int] = ...,
         rounding: Union[Literal["whole", "power_of_two"], int, None] = ...,
         aspect: float = ..., receivers: Optional[ArrayLike] = ...,
         casters: Optional[ArrayLike] = ..., depth_range: Optional[ArrayLike] = ...,
         depth_clamp: bool = ..., map_resolution: int = ...) -> dict[str, object]:
    """The cheapest scheme for a target error, or the least error for a texel budget: scheme,
    frame_kwargs, warp_args, resolutions (m, 2), max_error_pixels, texels, focus, candidates."""
def plan_clipmap(view: ArrayLike, near: float, far: float, half_fov: float, light_dir: Vec3, *,
                 image_height: int, aspect: float = ..., receivers: Optional[ArrayLike] = ...,
                 casters: Optional[ArrayLike] = ..., depth_range: Optional[ArrayLike] = ...,
                 depth_clamp: bool = ..., map_resolution: int = ...,
                 lod_bias: Optional[float] = ..., levels: Optional[ArrayLike] = ...,
                 level_unit: Optional[float] = ..., page_texels: Optional[int] = ...,
                 pool: Optional[int] = ..., max_error: Optional[float] = ...) -> dict[str, object]:
    """A clipmap's levels for the scene: lod_bias, bias_in_effect, first_level, last_level,
    pages, max_error_pixels, frame_kwargs, levels (level, depths, error_bound, texel,
    max_error_pixels, pages)."""
def sweep_angles(elevations: int, azimuths: int) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """The grid's elevations (both ends) and azimuths (2π excluded)."""
def sweep(near: float, far: float, half_fov: float, rule: str = ...,
          partition: Literal["single", "uniform", "log", "practical", "adaptive", "faces"] = ...,
          k: int = ..., *, elevations: int = ..., azimuths: int = ..., lambda_: Optional[float] = ...,
          eta: Optional[float] = ..., focus: Optional[float] = ..., near_hint: Optional[float] = ...,
          far_hint: Optional[float] = ..., shadow_distance: Optional[float] = ...,
          aspect: float = ...) -> npt.NDArray[np.float64]:
    """(elevations, azimuths) storage factor over the hemisphere, all cores, GIL released, in
    blocks of about 20 ms: Ctrl-C raises KeyboardInterrupt between two blocks."""
