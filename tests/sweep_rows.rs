//! A sweep computed block by block (`sweep_block_into`, as the Python bindings run it so that
//! Ctrl-C is seen between blocks) is the whole-grid sweep bit for bit, and reports the same
//! error for the same failing direction.

use shadow_aliasing::maps::WarpRule;
use shadow_aliasing::scheme::sweep::{
    light_dir_from_angles, sweep_block_into, sweep_into, SweepGrid,
};
use shadow_aliasing::scheme::{scheme, Partition};
use shadow_aliasing::{Error, ViewFrustum};
use std::ops::Range;

/// `sweep_block_into` over the blocks of `rows_per × cols_per` cells (the last ones shorter),
/// assembled into one grid-sized buffer.
fn by_blocks(
    view: &ViewFrustum,
    rule: WarpRule,
    partition: Partition,
    k: usize,
    grid: SweepGrid,
    rows_per: usize,
    cols_per: usize,
) -> Vec<f64> {
    let (e, a) = (grid.elevations(), grid.azimuths());
    let mut all = vec![f64::NAN; grid.len()];
    for r0 in (0..e).step_by(rows_per) {
        for c0 in (0..a).step_by(cols_per) {
            let (rows, cols) = (r0..(r0 + rows_per).min(e), c0..(c0 + cols_per).min(a));
            let mut block = vec![f64::NAN; rows.len() * cols.len()];
            sweep_block_into(
                view,
                rule,
                partition,
                k,
                grid,
                rows.clone(),
                cols.clone(),
                &mut block,
            )
            .unwrap();
            for (i, values) in rows.zip(block.chunks_exact(cols.len())) {
                all[i * a + cols.start..i * a + cols.end].copy_from_slice(values);
            }
        }
    }
    all
}

/// Every block shape (single cells, single rows, single columns, blocks straddling the 512-column
/// table of azimuths and the four-direction lanes) gives the whole sweep's values bit for bit, for
/// the lane-evaluated single maps, the scalar single maps, z-partitions and face partitions.
#[test]
fn blocks_are_the_whole_sweep_bit_for_bit() {
    let view = ViewFrustum::with_aspect(0.5, 800.0, 0.6, 1.5).unwrap();
    let cases = [
        (WarpRule::Lispsm, Partition::Single, 1),
        (WarpRule::Uniform, Partition::Single, 1),
        (WarpRule::Minimax, Partition::Single, 1),
        (WarpRule::Lispsm, Partition::Log, 3),
        (WarpRule::Lispsm, Partition::Faces, 2),
    ];
    for (rule, partition, k) in cases {
        // 517 columns: one full table of 512 azimuths and a short one.
        for grid in [
            SweepGrid::new(5, 517).unwrap(),
            SweepGrid::new(7, 9).unwrap(),
        ] {
            let mut whole = vec![0.0; grid.len()];
            sweep_into(&view, rule, partition, k, grid, &mut whole).unwrap();
            for (rows_per, cols_per) in [(1, 1), (1, 600), (2, 3), (3, 513), (8, 5), (1, 511)] {
                if grid.azimuths() > 100 && rows_per * cols_per < 4 {
                    continue; // single cells of the wide grid: covered by the small one
                }
                let blocks = by_blocks(&view, rule, partition, k, grid, rows_per, cols_per);
                for (n, (w, b)) in whole.iter().zip(&blocks).enumerate() {
                    assert_eq!(
                        w.to_bits(),
                        b.to_bits(),
                        "{rule:?} {partition:?} k={k} {grid:?} blocks {rows_per}×{cols_per}, \
                         cell {n}: whole {w} vs block {b}"
                    );
                }
            }
        }
    }
}

/// PSM at f/n = 10¹⁰ cannot be represented at some directions (found here by building the scheme
/// at each direction): a block holding the first such direction reports the whole sweep's error,
/// and a block holding none of them succeeds.
#[test]
fn a_block_reports_its_first_failing_direction_as_the_whole_sweep_does() {
    let view = ViewFrustum::new(1.0, 1e10, 0.5).unwrap();
    let grid = SweepGrid::new(9, 16).unwrap();
    let (rule, partition) = (WarpRule::Psm, Partition::Single);
    let fails = |i: usize, j: usize| {
        let l = light_dir_from_angles(grid.elevation(i), grid.azimuth(j));
        scheme(&view, l, rule, partition, 1).is_err()
    };
    let cells: Vec<(usize, usize)> = (0..9).flat_map(|i| (0..16).map(move |j| (i, j))).collect();
    let &(fi, fj) = cells
        .iter()
        .find(|&&(i, j)| fails(i, j))
        .expect("PSM at f/n = 1e10 fails at some direction of the grid");
    let mut whole = vec![0.0; grid.len()];
    let whole_err = sweep_into(&view, rule, partition, 1, grid, &mut whole).unwrap_err();
    let block = |rows: Range<usize>, cols: Range<usize>| {
        let mut out = vec![0.0; rows.len() * cols.len()];
        sweep_block_into(&view, rule, partition, 1, grid, rows, cols, &mut out).map(|()| out)
    };
    // The failing cell alone, and a block from it to the grid's end.
    assert_eq!(block(fi..fi + 1, fj..fj + 1).unwrap_err(), whole_err);
    assert_eq!(block(fi..9, fj..16).unwrap_err(), whole_err);
    // A row block holding no failing direction (if the grid has one) succeeds.
    if let Some(i) = (0..9).find(|&i| (0..16).all(|j| !fails(i, j))) {
        let values = block(i..i + 1, 0..16).unwrap();
        assert!(values.iter().all(|v| v.is_finite() && *v > 0.0));
    }
}

/// Ranges outside the grid and buffers of the wrong length are refused, naming the argument;
/// empty blocks are valid and write nothing.
#[test]
fn block_arguments_are_checked() {
    let view = ViewFrustum::new(1.0, 100.0, 0.5).unwrap();
    let grid = SweepGrid::new(4, 6).unwrap();
    let run = |rows: Range<usize>, cols: Range<usize>, len: usize| {
        let mut out = vec![0.0; len];
        sweep_block_into(
            &view,
            WarpRule::Lispsm,
            Partition::Single,
            1,
            grid,
            rows,
            cols,
            &mut out,
        )
    };
    let named = |r: Result<(), Error>, name: &str| match r {
        Err(Error::InvalidArgument { name: n, .. }) => assert_eq!(n, name),
        other => panic!("expected an error naming {name}, got {other:?}"),
    };
    named(run(0..5, 0..6, 30), "rows");
    #[allow(clippy::reversed_empty_ranges)]
    named(run(3..2, 0..6, 0), "rows");
    named(run(0..4, 2..7, 20), "cols");
    named(run(0..4, 0..6, 23), "out");
    assert_eq!(run(2..2, 0..6, 0), Ok(()));
    assert_eq!(run(0..4, 6..6, 0), Ok(()));
}
