//! Atlas layout (Lloyd 2005 Eq 6 and its x-then-z split): texels sum to the total, viewports are
//! disjoint and tile the texture, each partition's matrix composed with its viewport maps its
//! region into its rectangle.

mod common;
use common::config;
use glam::{DMat4, DVec3, DVec4};
use proptest::prelude::*;
use shadow_aliasing::maps::atlas::{allocate_texels, layout, AtlasEntry, MAX_ATLAS_ENTRIES};
use shadow_aliasing::maps::faces::{face_partitions, Face, FaceWarp};
use shadow_aliasing::ViewFrustum;

proptest! {
    #![proptest_config(config(256))]

    /// Eq 6 in whole texels: the allocation sums to the total and each share is within one texel
    /// of r_s e_i/Σ e_j.
    #[test]
    fn allocation_sums_to_total(
        errors in proptest::collection::vec(1e-6f64..1e6, 1..MAX_ATLAS_ENTRIES),
        total in 0u32..100_000,
    ) {
        let mut out = [0u32; MAX_ATLAS_ENTRIES];
        allocate_texels(&errors, total, &mut out).unwrap();
        let sum: u64 = out[..errors.len()].iter().map(|&v| u64::from(v)).sum();
        prop_assert_eq!(sum, u64::from(total));
        let esum: f64 = errors.iter().sum();
        for (i, e) in errors.iter().enumerate() {
            let share = f64::from(total) * e / esum;
            prop_assert!((f64::from(out[i]) - share).abs() < 1.0 + 1e-9);
        }
    }

    /// Viewports are inside the texture, pairwise disjoint, and tile it exactly; columns follow
    /// the groups' largest M_x and rows the members' M_z (Eq 6 along each axis).
    #[test]
    fn viewports_tile_the_texture(
        entries in proptest::collection::vec((0usize..4, 0.1f64..10.0, 0.1f64..10.0), 1..12),
        w in 1024u32..8192,
        h in 1024u32..8192,
    ) {
        let entries: Vec<AtlasEntry> = entries
            .into_iter()
            .map(|(group, max_mx, max_mz)| AtlasEntry { group, max_mx, max_mz })
            .collect();
        let atlas = layout(w, h, &entries).unwrap();
        let v = atlas.viewports();
        prop_assert_eq!(v.len(), entries.len());
        let mut area = 0u64;
        for (i, a) in v.iter().enumerate() {
            prop_assert!(a.width > 0 && a.height > 0);
            prop_assert!(a.x + a.width <= w && a.y + a.height <= h);
            area += a.texels();
            for b in &v[i + 1..] {
                let overlap_x = a.x < b.x + b.width && b.x < a.x + a.width;
                let overlap_y = a.y < b.y + b.height && b.y < a.y + a.height;
                prop_assert!(!(overlap_x && overlap_y), "{a:?} overlaps {b:?}");
            }
        }
        prop_assert_eq!(area, u64::from(w) * u64::from(h));
        // Column widths by Eq 6 over the groups' largest M_x (within one texel).
        let mut groups: Vec<usize> = entries.iter().map(|e| e.group).collect();
        groups.sort_unstable();
        groups.dedup();
        let gmax: Vec<f64> = groups
            .iter()
            .map(|g| entries.iter().filter(|e| e.group == *g).map(|e| e.max_mx).fold(0.0, f64::max))
            .collect();
        let gsum: f64 = gmax.iter().sum();
        for (gi, g) in groups.iter().enumerate() {
            let members: Vec<usize> = (0..entries.len()).filter(|&i| entries[i].group == *g).collect();
            let width = v[members[0]].width;
            prop_assert!((f64::from(width) - f64::from(w) * gmax[gi] / gsum).abs() < 1.0 + 1e-9);
            let zsum: f64 = members.iter().map(|&i| entries[i].max_mz).sum();
            for &i in &members {
                prop_assert_eq!(v[i].width, width);
                let share = f64::from(h) * entries[i].max_mz / zsum;
                prop_assert!((f64::from(v[i].height) - share).abs() < 1.0 + 1e-9);
            }
        }
    }
}

/// By hand: two groups, M_x 1 and 3 share 1000 columns as 250 and 750; the first group's M_z
/// 1, 2, 2 share 500 rows as 100, 200, 200.
#[test]
fn layout_by_hand() {
    let e = |group, max_mx, max_mz| AtlasEntry {
        group,
        max_mx,
        max_mz,
    };
    let entries = [
        e(1, 3.0, 5.0),
        e(0, 1.0, 1.0),
        e(0, 0.5, 2.0),
        e(0, 1.0, 2.0),
    ];
    let a = layout(1000, 500, &entries).unwrap();
    let v = a.viewports();
    assert_eq!((v[1].x, v[1].y, v[1].width, v[1].height), (0, 0, 250, 100));
    assert_eq!(
        (v[2].x, v[2].y, v[2].width, v[2].height),
        (0, 100, 250, 200)
    );
    assert_eq!(
        (v[3].x, v[3].y, v[3].width, v[3].height),
        (0, 300, 250, 200)
    );
    assert_eq!(
        (v[0].x, v[0].y, v[0].width, v[0].height),
        (250, 0, 750, 500)
    );
    assert_eq!(a.width(), 1000);
    assert_eq!(a.height(), 500);
    // The viewport matrix maps the clip square onto the rectangle: (−1, −1) → (2·250/1000 − 1,
    // −1), (1, 1) → (1, 1).
    let m = v[0].clip_matrix();
    let lo = m * DVec4::new(-1.0, -1.0, 0.3, 1.0);
    let hi = m * DVec4::new(1.0, 1.0, -0.2, 1.0);
    assert!((lo - DVec4::new(-0.5, -1.0, 0.3, 1.0)).length() < 1e-15);
    assert!((hi - DVec4::new(1.0, 1.0, -0.2, 1.0)).length() < 1e-15);
    // Bad inputs.
    assert!(layout(0, 10, &entries).is_err());
    assert!(layout(10, 0, &entries).is_err());
    assert!(layout(10, 10, &[]).is_err());
    assert!(layout(10, 10, &[e(0, f64::NAN, 1.0)]).is_err());
    assert!(layout(10, 10, &[e(0, 1.0, 0.0)]).is_err());
    // Too few rows for three members of one column.
    assert!(layout(10, 2, &entries[1..]).is_err());
    let mut out = [0u32; 2];
    assert!(allocate_texels(&[1.0, 1.0, 1.0], 10, &mut out).is_err());
    assert!(allocate_texels(&[], 10, &mut out).is_err());
    assert!(allocate_texels(&[1.0, -1.0], 10, &mut out).is_err());
}

/// Eq 6 equalises the error: after allocation each partition's error per texel, e_i/r_si, is
/// Σ e_j / r_s (exactly, when the shares are whole).
#[test]
fn eq6_equalises_error() {
    let errors = [1.0, 3.0, 4.0];
    let mut out = [0u32; 3];
    allocate_texels(&errors, 800, &mut out).unwrap();
    assert_eq!(out, [100, 300, 400]);
    for (e, r) in errors.iter().zip(out) {
        assert!((e / f64::from(r) - 8.0 / 800.0).abs() < 1e-15);
    }
}

fn clip(m: &DMat4, p: DVec3) -> DVec3 {
    let h = *m * DVec4::new(p.x, p.y, p.z, 1.0);
    assert!(h.w > 0.0);
    h.truncate() / h.w
}

/// Face partitions of one frame in one atlas, grouped as Lloyd 2005 §4.1 does (opposite faces
/// share a column, the near face its own): each matrix composed with its viewport maps its face
/// part's vertices into its rectangle of the atlas's clip space.
#[test]
fn composed_matrices_map_into_their_viewports() {
    let view = ViewFrustum::new(0.5, 500.0, 0.7).unwrap();
    for l in [
        DVec3::new(0.1, -0.3, -1.0),
        DVec3::new(-0.4, -0.5, 0.8),
        DVec3::new(0.0, 0.0, -1.0),
    ] {
        let parts = face_partitions(&view, l, FaceWarp::Lispsm, 3).unwrap();
        let entries: Vec<AtlasEntry> = parts
            .iter()
            .map(|p| AtlasEntry {
                group: match p.face {
                    Face::Left | Face::Right => 0,
                    Face::Bottom | Face::Top => 1,
                    _ => 2,
                },
                max_mx: p.error.max_mx,
                max_mz: p.error.max_mz,
            })
            .collect();
        let atlas = layout(4096, 4096, &entries).unwrap();
        for (i, p) in parts.iter().enumerate() {
            let v = atlas.viewports()[i];
            let m = atlas.compose(i, &p.shadow.matrix()).unwrap();
            let (x0, x1) = (
                -1.0 + 2.0 * f64::from(v.x) / 4096.0,
                -1.0 + 2.0 * f64::from(v.x + v.width) / 4096.0,
            );
            let (y0, y1) = (
                -1.0 + 2.0 * f64::from(v.y) / 4096.0,
                -1.0 + 2.0 * f64::from(v.y + v.height) / 4096.0,
            );
            for q in p.vertices {
                let c = clip(&m, q);
                let own = clip(&p.shadow.matrix(), q);
                assert!(
                    c.x >= x0 - 1e-9 && c.x <= x1 + 1e-9,
                    "{c} not in [{x0}, {x1}]"
                );
                assert!(c.y >= y0 - 1e-9 && c.y <= y1 + 1e-9);
                assert!((c.z - own.z).abs() < 1e-12, "depth unchanged");
            }
        }
        assert!(atlas.compose(parts.len(), &DMat4::IDENTITY).is_none());
    }
}

/// A scheme's own atlas: the maps of every partitioning packed, tiling the texture, each
/// composed matrix mapping its region's vertices into its viewport.
#[test]
fn scheme_atlas_holds_every_partition() {
    use shadow_aliasing::maps::WarpRule;
    use shadow_aliasing::scheme::{scheme, Partition};
    let view = ViewFrustum::new(0.5, 300.0, 0.6).unwrap();
    for partition in [Partition::Single, Partition::Log, Partition::Faces] {
        for l in [
            DVec3::new(0.2, -0.9, -0.3),
            DVec3::NEG_Z,
            DVec3::new(-0.5, -0.2, 0.8),
        ] {
            let r = scheme(&view, l, WarpRule::Lispsm, partition, 3).unwrap();
            let atlas = r.atlas(2048, 2048).unwrap();
            let texels: u64 = atlas.viewports().iter().map(|v| v.texels()).sum();
            assert_eq!(texels, 2048 * 2048);
            for (i, p) in r.partitions().iter().enumerate() {
                let v = atlas.viewports()[i];
                let m = atlas.compose(i, &p.matrix).unwrap();
                let pts: Vec<DVec3> = common::region_points(&view, p);
                for q in pts {
                    let c = clip(&m, q);
                    let x0 = -1.0 + 2.0 * f64::from(v.x) / 2048.0;
                    let x1 = -1.0 + 2.0 * f64::from(v.x + v.width) / 2048.0;
                    let y0 = -1.0 + 2.0 * f64::from(v.y) / 2048.0;
                    let y1 = -1.0 + 2.0 * f64::from(v.y + v.height) / 2048.0;
                    assert!(c.x >= x0 - 1e-9 && c.x <= x1 + 1e-9);
                    assert!(c.y >= y0 - 1e-9 && c.y <= y1 + 1e-9);
                }
            }
        }
    }
}
