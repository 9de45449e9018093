//! The light directions the hemisphere figures sample: lloyd2006-fig7's grid and the coarser
//! one of lloyd2006-worst-case, which takes every second row and column of it (so both figures
//! print the same worst case: `worst_case_is_fig7s_maximum`).

/// Elevation rows of the sweeps (both ends, every 2°).
pub(super) const ELEVATIONS: usize = 46;
/// Azimuth columns of the sweeps (every 2°).
pub(super) const AZIMUTHS: usize = 180;

/// Fig 7's own grid, every 1° (at 2° its cells showed as steps along the bands of fast
/// change near the horizon).
pub(super) const FIG7_ELEVATIONS: usize = 91;
/// Fig 7's azimuth columns, every 1°.
pub(super) const FIG7_AZIMUTHS: usize = 360;
