//! The controller's search on a cut with one resolution shared by every map (with a resolution
//! per map, `per_map.rs`): every allowed candidate built once at `max_resolution` and measured,
//! then the fewest texels that meet the target within each one's cap, else the least error at
//! its cap (the module documentation of `controller` states the rule).

use super::{build, nothing_to_plan, over_budget, Controller, Setup, MAX_NEIGHBOURS};
use crate::error::Result;
use crate::frame::{FrameInput, FrameScheme};
use crate::plan::candidates::candidates;

impl Controller {
    /// A cut: every allowed candidate built once at `max_resolution` and measured; with a
    /// shared resolution (`search_in`) the fewest texels that meet the target
    /// within each one's cap, else the least error at its cap; with a resolution per map, as
    /// `per_map.rs` says.
    pub(super) fn search(&mut self, input: &FrameInput<'_>) -> Result<(Setup, f64)> {
        self.allowed = match &self.options.candidates {
            Some(l) => l.clone(),
            None => candidates(input)
                .into_iter()
                .filter(|s| !matches!(s, FrameScheme::Clipmap(_)))
                .collect(),
        };
        self.missed = 0;
        let list = std::mem::take(&mut self.allowed);
        let found = if self.options.shared_resolution {
            self.search_in(input, &list)
        } else {
            self.search_each_in(input, &list)
        };
        if let Ok((_, e)) = found {
            self.found = e;
        }
        self.allowed = list;
        found
    }

    fn search_in(
        &mut self,
        input: &FrameInput<'_>,
        list: &[FrameScheme<'static>],
    ) -> Result<(Setup, f64)> {
        let top = self.options.max_resolution;
        let target = self.options.max_error;
        self.fractions.clear();
        // (texels, error at that resolution, index, resolution, cap) of those that meet the
        // target; (error at the cap, index, cap) of every one built.
        let mut meet: Vec<(u64, f64, usize, u32, u32)> = Vec::new();
        let mut least: Option<(f64, usize, u32)> = None;
        let mut errors: Vec<(f64, usize)> = Vec::new();
        let mut first_err = None;
        for (i, s) in list.iter().enumerate() {
            let err = match build(input, *s, top, self.options.max_maps, &mut self.scratch) {
                Ok(e) => e,
                Err(e) => {
                    first_err.get_or_insert(e);
                    continue;
                }
            };
            let n = self.scratch.maps().len();
            let Some(cap) = self.options.cap_for(n) else {
                first_err.get_or_insert_with(|| over_budget(n));
                continue;
            };
            let at_cap = err * f64::from(top) / f64::from(cap);
            errors.push((at_cap, i));
            if least.is_none_or(|(l, _, _)| at_cap < l) {
                least = Some((at_cap, i, cap));
            }
            if let Some(t) = target {
                if let Some(r) = self.resolution_for(err * f64::from(top), t, cap) {
                    let e = err * f64::from(top) / f64::from(r);
                    meet.push((n as u64 * u64::from(r).pow(2), e, i, r, cap));
                }
            }
        }
        meet.sort_by(|a, b| {
            (a.0, a.1, a.2)
                .partial_cmp(&(b.0, b.1, b.2))
                .expect("finite")
        });
        self.ranked.clear();
        if meet.is_empty() {
            errors.sort_by(|a, b| a.partial_cmp(b).expect("finite"));
            self.ranked
                .extend(errors.iter().take(MAX_NEIGHBOURS).map(|e| list[e.1]));
        } else {
            self.ranked
                .extend(meet.iter().take(MAX_NEIGHBOURS).map(|m| list[m.2]));
        }
        for &(_, _, i, r, cap) in &meet {
            if let Some(f) = self.fit(input, list[i], r, cap)? {
                self.least = false;
                return Ok(f);
            }
        }
        let Some((_, i, cap)) = least else {
            return Err(first_err.unwrap_or_else(nothing_to_plan));
        };
        let s = Setup::shared(list[i], cap);
        let err = self.build_kept(input, s)?;
        self.least = true;
        Ok((s, err))
    }
}
