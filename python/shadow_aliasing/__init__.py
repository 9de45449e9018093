"""The perspective aliasing error of shadow maps, from the Rust crate ``shadow-aliasing``.

Errors name the argument: ``TypeError`` for a wrong type, ``ValueError`` for a value outside
the domain (the crate's message). No function returns NaN (but ``error_image``'s ``fill``,
NaN by default, for pixels without a prediction).

Closed forms (NumPy broadcasting over every float argument, float64 out): ``mx``, ``mz``, ``max_mx``,
``max_mz``, ``storage_factor``, ``critical_resolution``, ``n_prime_lispsm``,
``n_prime_from_eta``, ``eta_from_n_prime``, ``distribution_g``, ``subdivided_max_error``,
``allocate_texels``, ``z_partition``, ``scheme_storage_factor``, ``tilted_mz``,
``generalized_n_prime``, ``gamma_lim``, ``tsm_eta``, ``zhang_eq``, ``zhang_ep``,
``zhang_eq_local``, ``zhang_ep_local`` (the names and arguments of docs/eval.md; ``lambda`` is
spelled ``lambda_``).

Builders (4×4 float64 matrices, eye space → light clip space, ``clip = M @ (x, y, z, 1)``):
``warp``, ``n_prime_for``, ``cascades``, ``faces``, ``tsm``. World-space frame API (the renderer's path: a view matrix,
scene boxes, every scheme; dict of arrays): ``frame``; the cheapest scheme for a target error or
a texel budget: ``plan``; a clipmap's levels, pages and LOD bias: ``plan_clipmap``; the cheapest set-up for an error
budget in every frame, kept from frame to frame, and its maps' per-point error lens:
``Controller``. Measurement: ``frustum_max``,
``point_error``; a captured frame's per-pixel error: ``error_image``. Hemisphere sweep: ``sweep`` (all cores),
``sweep_angles``.

Ctrl-C raises ``KeyboardInterrupt`` within a fraction of a second in every call that can run
long; a result larger than memory raises ``MemoryError`` before any work (docs/python.md).
"""

from ._native import (
    WARP_RULES,
    Controller,
    allocate_texels,
    cascades,
    critical_resolution,
    distribution_g,
    error_image,
    eta_from_n_prime,
    faces,
    frame,
    frustum_max,
    gamma_lim,
    generalized_n_prime,
    max_mx,
    max_mz,
    mx,
    mz,
    n_prime_for,
    n_prime_from_eta,
    n_prime_lispsm,
    plan,
    plan_clipmap,
    point_error,
    scheme_storage_factor,
    storage_factor,
    subdivided_max_error,
    sweep,
    sweep_angles,
    tilted_mz,
    tsm,
    tsm_eta,
    warp,
    z_partition,
    zhang_ep,
    zhang_ep_local,
    zhang_eq,
    zhang_eq_local,
)

__version__ = "0.1.0"

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
