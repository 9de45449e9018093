//! The command line's grammar (clap), with an example in every `--help`.

use clap::error::ErrorKind;
use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;
use std::process::ExitCode;

/// The mathematics of perspective aliasing in shadow maps: the papers' figures, their closed
/// forms from JSON, a camera's shadow matrices with their measured error, and hemisphere sweeps.
#[derive(Debug, Parser)]
#[command(
    name = "shadow-aliasing",
    version,
    after_help = "Examples:\n  shadow-aliasing figures --out figures\n  shadow-aliasing eval examples/eval-request.json\n  shadow-aliasing warp --near 1 --far 100 --half-fov 0.5236 --light-dir 0,-1,0 --warp lispsm\n  shadow-aliasing sweep --near 1 --far 1000 --half-fov 0.5236 --warp lispsm > sweep.csv"
)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Write every figure of the papers (PNG and SVG) into a directory.
    #[command(
        after_help = "Example:\n  shadow-aliasing figures --out figures --format svg --only lloyd2006-fig6 zhang-fig3"
    )]
    Figures(FiguresArgs),
    /// Evaluate closed forms from JSON (docs/eval.md): one object or an array of objects.
    #[command(
        after_help = "Example:\n  echo '{\"quantity\": \"storage_factor\", \"near\": 1, \"far\": 100, \"half_fov\": 0.5236, \"n_prime\": 11}' | shadow-aliasing eval\n\nExit status: 0 every request answered with a value, 1 at least one answered with an error\n(or standard output cannot be written), 2 the input is not JSON of the contract's shape."
    )]
    Eval(EvalArgs),
    /// Print a camera's shadow matrices for a light, with their measured aliasing error.
    #[command(
        after_help = "Example:\n  shadow-aliasing warp --near 1 --far 100 --half-fov 0.5236 --light-dir 0,-1,0 --warp lispsm --partition log --k 4 --json"
    )]
    Warp(WarpArgs),
    /// The storage factor over the hemisphere of light directions, as CSV or a NumPy array.
    #[command(
        after_help = "Examples:\n  shadow-aliasing sweep --near 1 --far 1000 --half-fov 0.5236 --warp lispsm --elevations 90 --azimuths 360 > sweep.csv\n  shadow-aliasing sweep --near 1 --far 1000 --half-fov 0.5236 --warp lispsm --format npy --output sweep.npy\n\nnpy: float64 array of shape (E, A), row i elevation i, column j azimuth j; with --output sweep.npy\nalso sweep.elevations.npy (E) and sweep.azimuths.npy (A), radians (only beside a regular file:\nnot beside /dev/null). Files are written whole or not at all.\n\nA direction without a solution (adaptive planes that do not exist: lower --ratio or --k) fails\nthe sweep, naming the first such direction.\n\nColumns: elevation,azimuth,storage_factor (radians). Elevation rows i = 0..E-1 at i·(π/2)/(E-1)\n(0 the horizon, π/2 overhead; both ends included; E = 1 is the zenith); azimuth columns j = 0..A-1 at j·2π/A\n(0 behind the viewer, π in front; 2π excluded)."
    )]
    Sweep(SweepArgs),
    /// The cheapest shadow set-up that meets a target error, or the least error within a texel
    /// budget, every candidate measured over the scene (docs/planning.md).
    #[command(
        after_help = "Examples:\n  shadow-aliasing plan --near 1 --far 1000 --half-fov 0.5236 --light-dir 0.3,-0.8,-0.4 --receivers=-50,-5,-100,50,0,0 --image-height 1080 --max-error 1\n  shadow-aliasing plan --near 1 --far 1000 --half-fov 0.5236 --light-dir 0.3,-0.8,-0.4 --image-height 1080 --budget-texels 16777216 --max-maps 4 --json\n\nwarp_args in the JSON are warp's flags for the chosen scheme: `warp` with the same camera and\nscene flags and these reproduces each map's M_x and M_z, and so the error\nmax(M_x H/res_s, M_z H/res_t) at the planned resolutions."
    )]
    Plan(PlanArgs),
    /// Run the error-budget controller over a camera path file (docs/paths.md).
    #[command(
        after_help = "Examples:\n  shadow-aliasing replay --path paths/walk.json --max-error 2 --json\n  shadow-aliasing replay --path paths/cut.json --max-error 1 --figure cut.svg\n  shadow-aliasing replay --path paths/flyover.json --budget-texels 16777216 --per-map"
    )]
    Replay(ReplayArgs),
}

/// `replay` arguments.
#[derive(Debug, clap::Args)]
pub struct ReplayArgs {
    /// The camera path file (JSON, docs/paths.md).
    #[arg(long, value_name = "FILE")]
    pub path: PathBuf,
    /// The target: the largest error allowed, pixels per texel (the fewest texels that meet it).
    #[arg(long = "max-error", value_name = "PX", allow_hyphen_values = true)]
    pub max_error: Option<f64>,
    /// The budget: texels of all maps together (with --max-error: the target within it, else
    /// the least error that fits; alone: the least error within it).
    #[arg(long = "budget-texels", value_name = "N", allow_hyphen_values = true)]
    pub budget_texels: Option<i64>,
    /// Each map its own resolution (separate textures or an atlas); without it every map
    /// shares one, as in Bevy and three.js.
    #[arg(long = "per-map")]
    pub per_map: bool,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// Also write a figure (SVG) of each frame's error, against the target, and texels.
    #[arg(long, value_name = "FILE")]
    pub figure: Option<PathBuf>,
}

/// `plan` arguments.
#[derive(Debug, clap::Args)]
pub struct PlanArgs {
    #[command(flatten)]
    pub camera: CameraArgs,
    /// Direction the light travels, eye space (camera at the origin looking down −Z, Y up): x,y,z.
    #[arg(long = "light-dir", value_name = "X,Y,Z", allow_hyphen_values = true, value_parser = parse_vec3)]
    pub light_dir: [f64; 3],
    #[command(flatten)]
    pub bounds: BoundsArgs,
    /// The image's height in pixels: errors are in these pixels per texel.
    #[arg(long = "image-height", value_name = "N", allow_hyphen_values = true)]
    pub image_height: i64,
    /// The target: the largest error allowed, pixels per texel (the plan is the fewest texels
    /// that meet it).
    #[arg(
        long = "max-error",
        value_name = "PX",
        allow_hyphen_values = true,
        conflicts_with = "budget_texels"
    )]
    pub max_error: Option<f64>,
    /// The budget: texels of all maps together (the plan is the least error within it).
    #[arg(long = "budget-texels", value_name = "N", allow_hyphen_values = true)]
    pub budget_texels: Option<i64>,
    /// With --budget-texels: the most maps a scheme may have (default 8).
    #[arg(long = "max-maps", value_name = "K", allow_hyphen_values = true)]
    pub max_maps: Option<i64>,
    /// Each map's resolution along each axis: any whole number of texels, or a power of two.
    #[arg(long, value_enum, default_value_t = RoundingName::Whole)]
    pub rounding: RoundingName,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

/// `--rounding`: the library's [`shadow_aliasing::plan::allocate::Rounding`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum RoundingName {
    /// Any whole number of texels.
    Whole,
    /// Powers of two.
    PowerOfTwo,
}

/// `figures` arguments.
#[derive(Debug, clap::Args)]
pub struct FiguresArgs {
    /// Directory to write into (created when missing).
    #[arg(long, value_name = "DIR", default_value = "figures")]
    pub out: PathBuf,
    /// Image format.
    #[arg(long, value_enum, default_value_t = Format::Both)]
    pub format: Format,
    /// Only these figures (for instance lloyd2006-fig7); all of them when absent.
    #[arg(
        long,
        value_name = "NAME",
        num_args = 1..,
        value_parser = clap::builder::PossibleValuesParser::new(shadow_aliasing::plot::FIGURES)
    )]
    pub only: Vec<String>,
    /// No title and no caption in the figures (for a document that sets its own caption): each is
    /// laid out as captioned and cut to the plot area between them.
    #[arg(long)]
    pub bare: bool,
    /// Multiply the PNG's pixel size (and the SVG's width and height) by this whole number, 1 to 8.
    // Signed, so that a negative scale reaches the range check instead of clap's "unexpected
    // argument".
    #[arg(
        long,
        value_name = "N",
        default_value_t = 1,
        allow_hyphen_values = true
    )]
    pub scale: i64,
    /// Pixels per inch recorded in the PNG (its pHYs chunk): printed size = pixels / DPI. By
    /// default the PNG prints at the SVG's and the PDF's size: 432 (6 pixels a unit, one unit a
    /// point) for --column double, 540 for single.
    #[arg(long, value_name = "DPI", allow_hyphen_values = true)]
    pub dpi: Option<f64>,
    /// Lay the figures out across a page's two columns (double, 520 pt = 7.22 in wide) or in one column
    /// (single, 240 pt = 3.33 in, text at least 6 pt, at most 420 pt tall; every figure has both).
    #[arg(long, value_enum, default_value_t = ColumnName::Double)]
    pub column: ColumnName,
}

/// `figures --column`: the library's [`shadow_aliasing::plot::Column`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ColumnName {
    /// Across both columns of a page: 520 units, 7.22 in wide.
    Double,
    /// One column: 300 units printed 3.33 in (240 pt) wide.
    Single,
}

/// Image formats of `figures`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// PNG only.
    Png,
    /// SVG only.
    Svg,
    /// PNG and SVG.
    Both,
    /// PDF only (vector, font embedded): needs the crate's feature `pdf`
    /// (in the clone: `cargo install --path . --features cli,pdf --locked`).
    Pdf,
}

/// `eval` arguments.
#[derive(Debug, clap::Args)]
pub struct EvalArgs {
    /// A JSON request file; standard input when absent or "-".
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,
}

/// The camera: view frustum of a square image.
#[derive(Debug, Clone, clap::Args)]
pub struct CameraArgs {
    /// Near plane depth (> 0).
    #[arg(long, allow_hyphen_values = true)]
    pub near: f64,
    /// Far plane depth (> near).
    #[arg(long, allow_hyphen_values = true)]
    pub far: f64,
    /// Half of the vertical field of view, radians (0 < half_fov < π/2).
    #[arg(long = "half-fov", value_name = "RADIANS", allow_hyphen_values = true)]
    pub half_fov: f64,
}

/// A scheme: warp rule and partition.
#[derive(Debug, Clone, clap::Args)]
pub struct SchemeArgs {
    /// The map and its n′ rule.
    #[arg(long, value_enum)]
    pub warp: WarpName,
    /// η ∈ [−1, 1] for `--warp eta` (−1 unwarped, 0 LiSPSM, 1 PSM).
    #[arg(long, allow_hyphen_values = true)]
    pub eta: Option<f64>,
    /// TSM's focus distance δ beyond the near plane of each map's (sub)frustum, world units
    /// (default: half the depth range of the shallowest z-partition).
    #[arg(long, allow_hyphen_values = true)]
    pub focus: Option<f64>,
    /// Filament's near hint (`ShadowOptions::shadowNearHint`), with `--warp filament`.
    #[arg(long = "near-hint", requires = "far_hint", allow_hyphen_values = true)]
    pub near_hint: Option<f64>,
    /// Filament's far hint (`ShadowOptions::shadowFarHint`), with `--warp filament`.
    #[arg(long = "far-hint", requires = "near_hint", allow_hyphen_values = true)]
    pub far_hint: Option<f64>,
    /// OGRE's shadowDist, world units, with `--warp ogre-ortho` (default: 300 × near, OGRE's
    /// own fallback when neither the shadow camera's far clip nor a shadow far distance is set).
    #[arg(long = "shadow-distance", allow_hyphen_values = true)]
    pub shadow_distance: Option<f64>,
    /// How the view frustum is partitioned.
    #[arg(long, value_enum, default_value_t = PartitionName::Single)]
    pub partition: PartitionName,
    /// Number of z-partitions (inside each face for `faces`), 1 to 16.
    ///
    /// Signed, so that a negative count reaches the domain check (`k must lie in [1, 16]`)
    /// instead of clap's "unexpected argument".
    #[arg(long, default_value_t = 1, allow_hyphen_values = true)]
    pub k: i64,
    /// Blend of `practical` partitions: 0 uniform, 1 logarithmic (default 0.5; only with
    /// `--partition practical`).
    #[arg(long, allow_hyphen_values = true)]
    pub lambda: Option<f64>,
    /// Barroso & Celes' far-partition ratio α > 1 of `adaptive` partitions: the depth ratio
    /// f_i/n_i of partitions 2..k when the light is parallel to the view (default 2, their
    /// Fig 9; only with `--partition adaptive`). The planes exist only while α is small enough
    /// for far/near at the light's angle (α^(k-1) < far/near with the light along the view):
    /// lower it, or --k, when told there is no solution.
    #[arg(long, allow_hyphen_values = true)]
    pub ratio: Option<f64>,
}

/// Warp rules by name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum WarpName {
    /// No warp: an orthographic map fitted to the frustum (n′ = ∞).
    Uniform,
    /// n′ from η (`--eta`).
    Eta,
    /// Perspective shadow map: n′ = n.
    Psm,
    /// LiSPSM: n′ = (n + √(f n))/sin γ of each (sub)frustum (Wimmer et al. 2004; Lloyd 2006
    /// §4.1, §4.4): the uniform map with the light behind or in front, worse than it for lights
    /// within about 25° of those directions (docs/builders.md); minimax never is.
    #[value(alias = "lispsm-sin")]
    Lispsm,
    /// LiSPSM's overhead n′ = n + √(f n) held fixed for every light direction (not LiSPSM away
    /// from overhead).
    LispsmFixed,
    /// Barroso & Celes' generalised n′ with their fall-off (Eq 18).
    Barroso,
    /// Barroso & Celes' generalised n′ with Zhang's fall-off (Eq 17).
    BarrosoZhang,
    /// The n′ that minimises the storage factor S̄ = M_x M_z of the fitted map, never worse than
    /// uniform (this crate; the library's default).
    Minimax,
    /// The n′ that minimises the maximum z error M_z alone (this crate).
    MinimaxMz,
    /// Trapezoidal shadow map with the 80% rule (Martin & Tan).
    Tsm,
    /// The LiSPSM reference code's d/(√(z1/z0) − 1).
    LispsmReference,
    /// Filament's rule (default hints, or `--near-hint` and `--far-hint`).
    Filament,
    /// OGRE's default rule, as OGRE 1.x through 13.5 build it.
    Ogre,
    /// OGRE 13.6 and later: n′ × shadowDist (`--shadow-distance`), from the orthographic camera.
    OgreOrtho,
    /// Martin & Tan's trapezoidal map of the focus body in its own view-axis light space, the
    /// 80 % rule, focus `--focus` (default half of far − near) (`warp` only, through the frame
    /// API: `FrameScheme::Tsm`).
    Trapezoid,
}

/// Partition schemes by name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum PartitionName {
    /// One map for the whole frustum.
    Single,
    /// z-partitions of equal depth.
    Uniform,
    /// Self-similar (logarithmic) z-partitions (Lloyd 2006 Eq 15, 16).
    Log,
    /// The λ-blend of uniform and logarithmic (`--lambda`).
    Practical,
    /// Barroso & Celes' adaptive z-partitions (Eq 19), γ from the light, α from `--ratio`
    /// (default 2).
    Adaptive,
    /// Face partitions (Lloyd 2006 §5.1), with `--k` z-partitions inside each face.
    Faces,
    /// `--k` cascades whose measured maximum errors over their focus bodies are equal
    /// (`CascadeSplits::EqualError`; `warp` only, through the frame API: the logarithmic splits
    /// for the frustum alone).
    EqualError,
    /// A clipmap, Unreal-style virtual shadow maps (`FrameScheme::Clipmap`; `warp` only): one
    /// orthographic level per depth range it is chosen for, options --lod-bias, --levels,
    /// --level-unit, --page-texels, --virtual-resolution, --image-height.
    Clipmap,
}

/// `warp` arguments.
#[derive(Debug, clap::Args)]
pub struct WarpArgs {
    #[command(flatten)]
    pub camera: CameraArgs,
    /// Direction the light travels, eye space (camera at the origin looking down −Z, Y up): x,y,z.
    #[arg(long = "light-dir", value_name = "X,Y,Z", allow_hyphen_values = true, value_parser = parse_vec3)]
    pub light_dir: [f64; 3],
    #[command(flatten)]
    pub scheme: SchemeArgs,
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The printed matrices' clip depth: OpenGL [-1, 1], [0, 1] (Vulkan, wgpu, Direct3D), or
    /// reversed [1, 0] (1 nearest the light, Bevy's cascades).
    #[arg(long = "clip-depth", value_enum, default_value_t = ClipDepthName::NegOneToOne)]
    pub clip_depth: ClipDepthName,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

/// `--clip-depth`: the library's [`shadow_aliasing::maps::ClipDepth`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ClipDepthName {
    /// z/w in [-1, 1], -1 nearest the light (OpenGL).
    NegOneToOne,
    /// z/w in [0, 1], 0 nearest the light (Vulkan, wgpu, Direct3D, Metal).
    ZeroToOne,
    /// z/w in [0, 1], 1 nearest the light (reversed depth).
    Reversed,
}

impl ClipDepthName {
    /// The library's convention.
    pub fn depth(self) -> shadow_aliasing::maps::ClipDepth {
        use shadow_aliasing::maps::ClipDepth;
        match self {
            Self::NegOneToOne => ClipDepth::NegOneToOne,
            Self::ZeroToOne => ClipDepth::ZeroToOne,
            Self::Reversed => ClipDepth::Reversed,
        }
    }

    /// The printed matrix's depth, in words.
    pub fn label(self) -> &'static str {
        match self {
            Self::NegOneToOne => "OpenGL depth [-1, 1]",
            Self::ZeroToOne => "depth [0, 1]",
            Self::Reversed => "reversed depth [1, 0], 1 nearest the light",
        }
    }
}

/// The scene of `warp` and `plan`: the maps focused on receivers ∩ the view (the library's frame
/// API), with the camera at the origin of eye space (world = eye).
#[derive(Debug, Clone, clap::Args)]
pub struct BoundsArgs {
    /// The image's width over its height (default 1, a square image); given, `warp` builds its
    /// maps with the frame API.
    #[arg(long, allow_hyphen_values = true)]
    pub aspect: Option<f64>,
    /// A receivers' box in eye space (repeatable; several merge into their bounding box).
    #[arg(long, value_name = "MINX,MINY,MINZ,MAXX,MAXY,MAXZ", allow_hyphen_values = true, value_parser = parse_box)]
    pub receivers: Vec<[f64; 6]>,
    /// A casters' box in eye space (repeatable): extends each map's depth toward the light.
    #[arg(long, value_name = "MINX,MINY,MINZ,MAXX,MAXY,MAXZ", allow_hyphen_values = true, value_parser = parse_box)]
    pub casters: Vec<[f64; 6]>,
    /// The visible receivers' depth range (a depth-buffer min/max reduction).
    #[arg(long = "depth-range", value_name = "ZMIN,ZMAX", allow_hyphen_values = true, value_parser = parse_pair)]
    pub depth_range: Option<[f64; 2]>,
    /// The device clamps depth: casters are not put in the depth range.
    #[arg(long = "depth-clamp")]
    pub depth_clamp: bool,
}

impl BoundsArgs {
    /// Whether any of these options is given.
    pub fn any(&self) -> bool {
        self.aspect.is_some()
            || !self.receivers.is_empty()
            || !self.casters.is_empty()
            || self.depth_range.is_some()
            || self.depth_clamp
    }
}

/// `warp`'s scene: the bounds, and cascades given by their planes (the library's frame API).
#[derive(Debug, Clone, clap::Args)]
pub struct SceneArgs {
    #[command(flatten)]
    pub bounds: BoundsArgs,
    /// Stable cascades (world-fixed, texel-snapped squares; unwarped: with --warp uniform) with
    /// the splits of --partition, --splits, --fractions or --bevy (one map with none of them).
    #[arg(long)]
    pub stable: bool,
    /// Cascades at absolute split distances Z0,Z1,...,ZK (first near to last far).
    #[arg(long, value_name = "Z0,...,ZK", allow_hyphen_values = true, value_parser = parse_list, conflicts_with_all = ["fractions", "bevy"])]
    pub splits: Option<NumList>,
    /// Cascades at fractions F1,...,F(K-1) of the depth range.
    #[arg(long, value_name = "F1,...", allow_hyphen_values = true, value_parser = parse_list, conflicts_with = "bevy")]
    pub fractions: Option<NumList>,
    /// Bevy's cascades: K,MINIMUM_DISTANCE,FIRST_FAR_BOUND,MAXIMUM_DISTANCE,OVERLAP_PROPORTION.
    #[arg(long, value_name = "K,MIN,FIRST_FAR,MAX,OVERLAP", allow_hyphen_values = true, value_parser = parse_list)]
    pub bevy: Option<NumList>,
    /// Cascade overlap fraction in [0, 1) (with --partition, --splits or --fractions; --bevy
    /// takes its own OVERLAP_PROPORTION).
    #[arg(long, allow_hyphen_values = true, conflicts_with = "bevy")]
    pub overlap: Option<f64>,
    #[command(flatten)]
    pub clipmap: Box<ClipmapArgs>,
}

/// `--partition clipmap`'s options (defaults: Unreal 5's, for a world in metres), each refused
/// without `--partition clipmap`.
#[derive(Debug, Clone, clap::Args)]
pub struct ClipmapArgs {
    /// With --partition clipmap: the LOD bias b, the chosen level's texel being at most 2^b
    /// pixels (default: Unreal's -0.5).
    #[arg(long = "lod-bias", value_name = "B", allow_hyphen_values = true)]
    pub lod_bias: Option<f64>,
    /// With --partition clipmap: the finest and coarsest levels, level i covering radius
    /// 2^(i+1) units (default: Unreal's 6,22).
    #[arg(long, value_name = "FIRST,LAST", allow_hyphen_values = true, value_parser = parse_list)]
    pub levels: Option<NumList>,
    /// With --partition clipmap: the world length of a level unit (default 0.01: metres,
    /// Unreal's levels being in centimetres).
    #[arg(long = "level-unit", value_name = "U", allow_hyphen_values = true)]
    pub level_unit: Option<f64>,
    /// With --partition clipmap: texels per page side (default: Unreal's 128).
    #[arg(long = "page-texels", value_name = "P", allow_hyphen_values = true)]
    pub page_texels: Option<i64>,
    /// With --partition clipmap: texels per level side (default: Unreal's 16384).
    #[arg(
        long = "virtual-resolution",
        value_name = "R",
        allow_hyphen_values = true
    )]
    pub virtual_resolution: Option<i64>,
    /// With --partition clipmap: the image's height in pixels that the levels are chosen for
    /// (default 1080).
    #[arg(long = "image-height", value_name = "H", allow_hyphen_values = true)]
    pub image_height: Option<i64>,
}

impl ClipmapArgs {
    /// The options given, by the names their messages use, with whether each is given.
    pub fn given(&self) -> [(&'static str, bool); 6] {
        [
            ("lod_bias", self.lod_bias.is_some()),
            ("levels", self.levels.is_some()),
            ("level_unit", self.level_unit.is_some()),
            ("page_texels", self.page_texels.is_some()),
            ("virtual_resolution", self.virtual_resolution.is_some()),
            ("image_height", self.image_height.is_some()),
        ]
    }
}

impl SceneArgs {
    /// Whether any scene option is given (then `warp` uses the frame API).
    pub fn any(&self) -> bool {
        self.bounds.any()
            || self.stable
            || self.splits.is_some()
            || self.fractions.is_some()
            || self.bevy.is_some()
            || self.overlap.is_some()
    }
}

/// `sweep` arguments.
#[derive(Debug, clap::Args)]
pub struct SweepArgs {
    #[command(flatten)]
    pub camera: CameraArgs,
    #[command(flatten)]
    pub scheme: SchemeArgs,
    /// Number of elevation rows, evenly over [0, π/2] both ends included (1 gives the zenith only).
    #[arg(long, default_value_t = 90, allow_hyphen_values = true)]
    pub elevations: i64,
    /// Number of azimuth columns, evenly over [0, 2π), 2π excluded (≥ 1).
    #[arg(long, default_value_t = 360, allow_hyphen_values = true)]
    pub azimuths: i64,
    /// Worker threads, 1 to 1024 (default: all cores).
    #[arg(long, value_name = "T", allow_hyphen_values = true, value_parser = parse_threads)]
    pub threads: Option<usize>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = SweepFormat::Csv)]
    pub format: SweepFormat,
    /// Write to FILE instead of standard output ("-" is standard output). With `--format npy`,
    /// the axes go beside a regular FILE: FILE.npy gives FILE.elevations.npy and
    /// FILE.azimuths.npy. Files are replaced whole or left as they were.
    #[arg(long, value_name = "FILE")]
    pub output: Option<PathBuf>,
}

/// Output formats of `sweep`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SweepFormat {
    /// Text: elevation,azimuth,storage_factor, one row per direction.
    Csv,
    /// NumPy .npy: the storage factors as a little-endian float64 array of shape
    /// (elevations, azimuths).
    Npy,
}

/// The largest `--threads`: far more than a sweep can use on any machine (it is CPU-bound, so
/// threads beyond the cores only wait), and far below the operating system's limits on threads
/// and memory maps, whose exhaustion inside a worker would otherwise panic it and hang the pool.
pub const MAX_THREADS: usize = 1024;

/// Parses `--threads`: a whole number in [1, [`MAX_THREADS`]].
fn parse_threads(s: &str) -> Result<usize, String> {
    let t = s.trim();
    let digits = t.strip_prefix(['-', '+']).unwrap_or(t);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err(format!(
            "expected a whole number of threads in [1, {MAX_THREADS}] (got {s:?})"
        ));
    }
    match t.parse::<i128>() {
        Ok(v) if (1..=MAX_THREADS as i128).contains(&v) => {
            usize::try_from(v).map_err(|_| format!("must lie in [1, {MAX_THREADS}] (got {t})"))
        }
        // Out of range, however many digits it has.
        _ => Err(format!("must lie in [1, {MAX_THREADS}] (got {t})")),
    }
}

/// A comma-separated list of numbers (a newtype: clap reads `Option<Vec<_>>` as repeated values).
#[derive(Debug, Clone, PartialEq)]
pub struct NumList(pub Vec<f64>);

/// Parses a comma-separated list of finite numbers.
fn parse_list(s: &str) -> Result<NumList, String> {
    parse_numbers(s).map(NumList)
}

fn parse_numbers(s: &str) -> Result<Vec<f64>, String> {
    s.split(',')
        .map(str::trim)
        .map(|p| match p.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            Ok(_) => Err(format!("expected finite numbers (got {p})")),
            Err(_) => Err(format!(
                "expected numbers separated by commas ({p:?} is not a number)"
            )),
        })
        .collect()
}

fn parse_n<const N: usize>(s: &str, what: &str) -> Result<[f64; N], String> {
    let v = parse_numbers(s)?;
    <[f64; N]>::try_from(v.as_slice())
        .map_err(|_| format!("expected {N} numbers {what} (got {s:?})"))
}

/// Parses `minx,miny,minz,maxx,maxy,maxz`.
fn parse_box(s: &str) -> Result<[f64; 6], String> {
    parse_n::<6>(s, "MINX,MINY,MINZ,MAXX,MAXY,MAXZ")
}

/// Parses `a,b`.
fn parse_pair(s: &str) -> Result<[f64; 2], String> {
    parse_n::<2>(s, "ZMIN,ZMAX")
}

/// Parses `x,y,z`.
fn parse_vec3(s: &str) -> Result<[f64; 3], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(format!("expected three numbers x,y,z (got {s:?})"));
    }
    let mut out = [0.0; 3];
    for (o, p) in out.iter_mut().zip(&parts) {
        *o = p
            .parse::<f64>()
            .map_err(|_| format!("expected three numbers x,y,z ({p:?} is not a number)"))?;
        if !o.is_finite() {
            return Err(format!("expected three finite numbers x,y,z (got {p})"));
        }
    }
    Ok(out)
}

/// Prints help and version as clap does; any other parse error as one line, exit status 2.
pub fn clap_exit(e: &clap::Error) -> ExitCode {
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            let _ = e.print();
            ExitCode::SUCCESS
        }
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let _ = e.print();
            ExitCode::from(2)
        }
        _ => {
            let text = e.render().to_string();
            let first = one_line(&text);
            let hint = if first.contains("--help") {
                String::new()
            } else {
                " (see --help)".to_string()
            };
            crate::commands::to_stderr(&format!("{first}{hint}\n"));
            ExitCode::from(2)
        }
    }
}

/// The first paragraph of clap's message on one line: "error: the following required
/// arguments were not provided: --far <FAR> --half-fov <RADIANS>".
fn one_line(text: &str) -> String {
    let mut out = String::new();
    for line in text.lines().skip_while(|l| l.trim().is_empty()) {
        if line.trim().is_empty() {
            break;
        }
        if !out.is_empty() {
            out.push(' ');
        }
        out.push_str(line.trim());
    }
    if out.is_empty() {
        "error: invalid arguments".to_string()
    } else {
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vec3_parsing() {
        assert_eq!(parse_vec3("0,-1,0"), Ok([0.0, -1.0, 0.0]));
        assert_eq!(parse_vec3(" 1, 2 ,3"), Ok([1.0, 2.0, 3.0]));
        assert!(parse_vec3("1,2").is_err());
        assert!(parse_vec3("1,x,2").is_err());
        assert!(parse_vec3("1,inf,2").is_err());
        assert_eq!(parse_vec3("-1,-0.5,-1e-3"), Ok([-1.0, -0.5, -1e-3]));
    }

    #[test]
    fn threads_parsing() {
        assert_eq!(parse_threads("1"), Ok(1));
        assert_eq!(parse_threads("1024"), Ok(MAX_THREADS));
        for bad in [
            "0",
            "-1",
            "1025",
            "20000",
            "18446744073709551615",
            "1e3",
            "x",
            "",
        ] {
            assert!(parse_threads(bad).is_err(), "{bad}");
        }
        assert_eq!(
            parse_threads("18446744073709551616000000000000000000000000"),
            Err("must lie in [1, 1024] (got 18446744073709551616000000000000000000000000)".into())
        );
    }

    /// docs/cli.md: negative numbers are values wherever a number is expected. Every option of
    /// every subcommand that takes a value, other than the named non-numeric ones, reads `-1`
    /// as its value: parsed, or refused by its own parser with the value, never clap's
    /// "unexpected argument".
    #[test]
    fn every_numeric_option_takes_a_negative_number() {
        use clap::CommandFactory;
        // Options whose values are names or paths, not numbers.
        const NOT_NUMBERS: [&str; 6] = ["out", "only", "output", "file", "path", "figure"];
        // Each subcommand's required options, then options that others need beside them.
        let base = |sub: &str| -> Vec<(&'static str, &'static str)> {
            let view = [("near", "1"), ("far", "100"), ("half-fov", "0.5")];
            let mut v = view.to_vec();
            match sub {
                "warp" => v.extend([("light-dir", "0,-1,0"), ("warp", "uniform")]),
                "sweep" => v.push(("warp", "uniform")),
                "plan" => v.extend([
                    ("light-dir", "0,-1,0"),
                    ("image-height", "1080"),
                    ("max-error", "1"),
                ]),
                "replay" => {
                    v.clear();
                    v.extend([("path", "p.json"), ("max-error", "1")]);
                }
                _ => v.clear(),
            }
            v
        };
        let companions: [(&str, &[(&str, &str)]); 4] = [
            ("near-hint", &[("far-hint", "1")]),
            ("far-hint", &[("near-hint", "1")]),
            ("budget-texels", &[]),
            ("max-maps", &[("budget-texels", "100")]),
        ];
        let cli = Cli::command();
        let mut checked = Vec::new();
        for sub in cli.get_subcommands() {
            let name = sub.get_name();
            for arg in sub.get_arguments() {
                let Some(long) = arg.get_long() else { continue };
                let takes_value = arg.get_action().takes_values();
                let enumerated = !arg.get_possible_values().is_empty();
                if !takes_value || enumerated || NOT_NUMBERS.contains(&long) {
                    continue;
                }
                let mut pairs = base(name);
                let extra = companions
                    .iter()
                    .find(|(c, _)| *c == long)
                    .map_or(&[][..], |(_, e)| *e);
                if !extra.is_empty() || long == "budget-texels" {
                    // `--max-error` conflicts with the budget's options.
                    pairs.retain(|(f, _)| *f != "max-error");
                }
                pairs.extend_from_slice(extra);
                pairs.retain(|(f, _)| *f != long);
                let mut argv = vec!["shadow-aliasing".to_string(), name.to_string()];
                for (f, v) in &pairs {
                    argv.extend([format!("--{f}"), (*v).to_string()]);
                }
                argv.extend([format!("--{long}"), "-1".to_string()]);
                let id = arg.get_id().as_str();
                match cli.clone().try_get_matches_from(&argv) {
                    Ok(m) => {
                        let (_, sm) = m.subcommand().expect("a subcommand");
                        let raw: Vec<_> = sm.get_raw(id).expect("given").collect();
                        assert_eq!(raw, ["-1"], "{argv:?}");
                    }
                    Err(e) => {
                        assert_eq!(e.kind(), ErrorKind::ValueValidation, "{argv:?}: {e}");
                        assert!(e.to_string().contains("-1"), "{argv:?}: {e}");
                    }
                }
                checked.push(format!("{name} --{long}"));
            }
        }
        // The iteration reached the options issue 31 names, and those of every subcommand.
        for must in [
            "figures --scale",
            "figures --dpi",
            "warp --k",
            "warp --lod-bias",
            "warp --levels",
            "warp --light-dir",
            "sweep --threads",
            "plan --max-maps",
            "plan --image-height",
            "replay --max-error",
        ] {
            assert!(
                checked.iter().any(|c| c == must),
                "{must} not checked: {checked:?}"
            );
        }
    }

    #[test]
    fn grammar_is_consistent() {
        use clap::CommandFactory;
        Cli::command().debug_assert();
    }
}
