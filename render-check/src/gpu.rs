//! wgpu on its Vulkan backend, headless: the shadow pass (one depth layer per map) and the
//! camera pass (texel coordinates, surface id, shaded colour, light clip depth), read back to
//! the CPU.

use bytemuck::{Pod, Zeroable};
use glam::{DMat4, DVec3};
use shadow_aliasing::frame::{GpuShadowMap, SHADOW_WGSL};
use std::ops::Range;

mod readback;

/// What to do when no adapter exists: the message names the package.
pub const NO_ADAPTER: &str = "no Vulkan adapter found: install a Vulkan driver; without a GPU, \
     Debian's software rasterizer: `apt-get update && apt-get install -y mesa-vulkan-drivers` \
     (scripts/test.sh does this)";

/// The first Vulkan adapter's device and queue (a GPU if there is one, else lavapipe), with
/// its name, driver and backend: what [`Gpu::new`] draws with, and what a test that runs the
/// WGSL module in a compute pass asks for.
///
/// # Errors
/// [`NO_ADAPTER`] when none is found; the device's error otherwise.
pub fn device(label: &str) -> Result<(wgpu::Device, wgpu::Queue, String), String> {
    let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
    desc.backends = wgpu::Backends::VULKAN;
    let instance = wgpu::Instance::new(desc);
    let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
        power_preference: wgpu::PowerPreference::HighPerformance,
        force_fallback_adapter: false,
        compatible_surface: None,
        ..Default::default()
    }))
    .map_err(|e| format!("{NO_ADAPTER} ({e})"))?;
    let info = adapter.get_info();
    let name = format!(
        "{} ({}, {:?}, {:?})",
        info.name, info.driver_info, info.device_type, info.backend
    );
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        label: Some(label),
        required_features: wgpu::Features::empty(),
        required_limits: adapter.limits(),
        ..Default::default()
    }))
    .map_err(|e| format!("requesting a device of {name}: {e}"))?;
    Ok((device, queue, name))
}

/// The device.
pub struct Gpu {
    device: wgpu::Device,
    queue: wgpu::Queue,
    /// The adapter's name, driver and backend.
    pub name: String,
    /// Shadow pipelines by `[reversed depth][first-surface maps]`.
    shadow_pipelines: [[wgpu::RenderPipeline; 2]; 2],
    camera_pipeline: wgpu::RenderPipeline,
    shadow_bgl: wgpu::BindGroupLayout,
    camera_bgl: wgpu::BindGroupLayout,
}

/// What the shadow maps store and how the lookup keeps a lit surface from shadowing itself.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Lookup {
    /// Second-depth maps (only faces turned away from the light are stored) with the hand-set
    /// rasterizer bias [`SLOPE_BIAS`], [`CONSTANT_BIAS`]; no receiver-side bias.
    SecondDepth,
    /// Ordinary first-surface maps (every face stored, no rasterizer bias): the lookup point moved
    /// by the record's normal offset (`FrameMap::bias`, the crate's module's `SA_NORMAL_OFFSET`).
    FirstSurface,
}

/// A camera-pass frame.
pub struct FrameInput<'a> {
    /// Triangle vertices relative to the upload origin (world axes).
    pub positions: &'a [DVec3],
    /// World-space normal of each vertex's surface.
    pub normals: &'a [DVec3],
    /// Surface id of each vertex.
    pub surface: &'a [u32],
    /// Relative position → camera clip (wgpu: depth [0, 1], NDC y up).
    pub rel_to_clip: DMat4,
    /// Relative position → eye space.
    pub rel_to_eye: DMat4,
    /// Unit world-space light direction (travel).
    pub light: DVec3,
    /// Unit eye-space light direction (travel).
    pub light_eye: DVec3,
    /// 0 single, 1 cascades, 2 faces, 3 clipmap.
    pub mode: u32,
    /// Clipmaps: `sa_clipmap_level`'s offset (`LevelChoice::offset`), the first and the last
    /// map's level (`FrameMap::clipmap_level`); unused by the other modes.
    pub clipmap: [f64; 3],
    /// The fault `blend-ignored`: a cascade shaded by its first map alone inside the blend band.
    pub one_map_in_band: bool,
    /// near, far, tan(θ), tan(θ)·aspect.
    pub frustum: [f64; 4],
    /// The maps' records as uploaded (one clip-depth convention for all).
    pub maps: &'a [GpuShadowMap],
    /// Per map: the vertex ranges drawn into it (culling).
    pub draws: &'a [Vec<Range<u32>>],
    /// Added (in `f32`) to a relative position before a map's matrix.
    pub offset: DVec3,
    /// The maps' kind and bias.
    pub lookup: Lookup,
    /// Map resolution (square).
    pub res: u32,
    /// Screen size.
    pub width: u32,
    /// Screen size.
    pub height: u32,
}

impl FrameInput<'_> {
    /// Whether the maps use reversed depth (greater-equal).
    fn reversed(&self) -> bool {
        self.maps.first().is_some_and(|m| {
            m.clip_depth
                == GpuShadowMap::clip_depth_code(shadow_aliasing::maps::ClipDepth::Reversed)
        })
    }
}

/// One camera pass of [`Gpu::render_paths`] over the same shadow maps.
#[derive(Clone, Copy)]
pub struct PathPass<'a> {
    /// The records looked up (one per map; their matrices the maps were drawn with).
    pub records: &'a [GpuShadowMap],
    /// `sa_visibility`'s bias flags (`SA_NORMAL_OFFSET` 1, `SA_DEPTH_BIAS` 2,
    /// `SA_LOCAL_NORMAL_OFFSET` 4).
    pub flags: u32,
    /// The PCF radius r passed to `sa_visibility` ((2r + 1)² taps).
    pub radius: u32,
    /// Whether the pass draws the error lens (`FrameOutput::lens`, `overlay`); without it the
    /// overlay holds the no-map values and `lens` the lookup's normal offset (`FrameOutput::lens`).
    pub lens: bool,
}

/// What the camera pass wrote.
pub struct FrameOutput {
    /// Per pixel (row-major from the top): s·res, t·res, map (the number of maps: none), the
    /// visibility shaded (0 in shadow, 1 lit; between them in a cascade's blend band).
    pub texel: Vec<[f32; 4]>,
    /// Surface id + 1 (0: sky).
    pub id: Vec<u32>,
    /// Shaded colour, RGBA8.
    pub color: Vec<[u8; 4]>,
    /// Depth (depth-attachment units) in the selected map, unclamped (inside its depth range:
    /// [0, 1]; −10³⁰ behind its centre of projection or with no map).
    pub depth: Vec<f32>,
    /// Per pixel: the second map (`sa_pick_cascade`'s; the first map elsewhere), its weight, the
    /// visibility of the first map alone and of the second alone (`texel`'s last component is
    /// the visibility shaded: cross-faded in a cascade's blend band).
    pub blend: Vec<[f32; 4]>,
    /// Per pixel: the error lens of the selected map (`sa_error_lens`, pixels), and the same with
    /// the projection factor 1 (the surface facing the light, seen along the light from the same
    /// view depth); 0 for the sky, −2 with no map, −1 behind the camera or the map's centre of
    /// projection, 3.4·10³⁸ edge-on to the light. In a pass without the lens
    /// ([`PathPass::lens`] false): the normal offset (world units) `sa_visibility` moves the
    /// lookup point by in the selected map for the pass's flags and radius (0 with neither offset
    /// flag), and 0, at pixels facing the light with a map; −2 elsewhere.
    pub lens: Vec<[f32; 2]>,
    /// The lens drawn over the scene: `sa_lens_colour` of the lens, 3/4, over the shaded colour,
    /// 1/4 (the shaded colour alone with no map), RGBA8.
    pub overlay: Vec<[u8; 4]>,
}

#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct GlobalsRaw {
    rel_to_clip: [f32; 16],
    rel_to_eye: [f32; 16],
    light: [f32; 4],
    light_eye: [f32; 4],
    frustum: [f32; 4],
    misc: [f32; 4],
    offset: [f32; 4],
    clipmap: [f32; 4],
    faults: [f32; 4],
}

#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct Vertex {
    pos: [f32; 3],
    normal: [f32; 3],
    id: u32,
}

/// The shaders' source: the crate's WGSL module ([`SHADOW_WGSL`]) followed by render-check's
/// own passes (`shaders.wgsl`), which select and look up the maps with the module's functions.
pub fn shader_source() -> String {
    shader_source_with(SHADOW_WGSL)
}

/// [`shader_source`] with `module` in place of the crate's module (a fault changes it).
pub fn shader_source_with(module: &str) -> String {
    format!("{module}\n{}", include_str!("shaders.wgsl"))
}

/// Slope-scaled depth bias of the second-depth shadow pass (in units of the depth slope per
/// texel) and its constant part (in units of the depth format's resolution at the primitive's
/// depth); negated for reversed depth. First-surface maps have none (the crate's bias instead).
pub const SLOPE_BIAS: f32 = 0.5;
/// See [`SLOPE_BIAS`].
pub const CONSTANT_BIAS: i32 = 16;

/// The bias flag of `sa_visibility` (the crate's module) for a lookup.
fn bias_flags(lookup: Lookup) -> u32 {
    match lookup {
        Lookup::SecondDepth => 0,
        Lookup::FirstSurface => 4, // SA_LOCAL_NORMAL_OFFSET
    }
}

fn mat(m: DMat4) -> [f32; 16] {
    m.as_mat4().to_cols_array()
}

fn vec4(v: DVec3, w: f32) -> [f32; 4] {
    [v.x as f32, v.y as f32, v.z as f32, w]
}

impl Gpu {
    /// The first Vulkan adapter (a GPU if there is one, else lavapipe).
    ///
    /// # Errors
    /// [`NO_ADAPTER`] when none is found; the device's error otherwise.
    pub fn new() -> Result<Self, String> {
        Self::with_source(&shader_source())
    }

    /// As [`Gpu::new`], with the shaders' source given: [`shader_source`] changed on purpose
    /// (render-check/tests/lens.rs breaks the module's `sa_error_lens` to show the lens targets
    /// catch it).
    ///
    /// # Errors
    /// As [`Gpu::new`]; a source that does not compile.
    pub fn with_source(source: &str) -> Result<Self, String> {
        let (device, queue, name) = device("render-check")?;
        // wgpu panics on an uncaptured validation error: every call below is scoped, so that an
        // error is returned instead.
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("shaders"),
            source: wgpu::ShaderSource::Wgsl(source.into()),
        });
        let shadow_bgl = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("shadow"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            }],
        });
        let camera_bgl = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("camera"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Storage { read_only: true },
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 2,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Depth,
                        view_dimension: wgpu::TextureViewDimension::D2Array,
                        multisampled: false,
                    },
                    count: None,
                },
            ],
        });
        let shadow_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("shadow"),
            bind_group_layouts: &[Some(&shadow_bgl)],
            immediate_size: 0,
        });
        let camera_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("camera"),
            bind_group_layouts: &[Some(&camera_bgl)],
            immediate_size: 0,
        });
        // Second-depth maps draw back faces only (`fs_shadow`) with the hand-set rasterizer bias;
        // first-surface maps draw every face, no fragment stage, no bias. Reversed depth compares
        // greater-equal, its bias pushing away from the light (toward 0).
        let shadow_pipeline = |reversed: bool, first_surface: bool| {
            let sign = if reversed { -1 } else { 1 };
            let bias = if first_surface {
                wgpu::DepthBiasState::default()
            } else {
                wgpu::DepthBiasState {
                    constant: sign * CONSTANT_BIAS,
                    slope_scale: sign as f32 * SLOPE_BIAS,
                    clamp: 0.0,
                }
            };
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("shadow"),
                layout: Some(&shadow_layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_shadow"),
                    compilation_options: Default::default(),
                    buffers: &[Some(wgpu::VertexBufferLayout {
                        array_stride: std::mem::size_of::<Vertex>() as u64,
                        step_mode: wgpu::VertexStepMode::Vertex,
                        attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3],
                    })],
                },
                primitive: wgpu::PrimitiveState::default(),
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: wgpu::TextureFormat::Depth32Float,
                    depth_write_enabled: Some(true),
                    depth_compare: Some(if reversed {
                        wgpu::CompareFunction::GreaterEqual
                    } else {
                        wgpu::CompareFunction::Less
                    }),
                    stencil: Default::default(),
                    bias,
                }),
                multisample: Default::default(),
                fragment: (!first_surface).then_some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some("fs_shadow"),
                    compilation_options: Default::default(),
                    targets: &[],
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        let shadow_pipelines = [
            [shadow_pipeline(false, false), shadow_pipeline(false, true)],
            [shadow_pipeline(true, false), shadow_pipeline(true, true)],
        ];
        let camera_pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("camera"),
            layout: Some(&camera_layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_camera"),
                compilation_options: Default::default(),
                buffers: &[Some(wgpu::VertexBufferLayout {
                    array_stride: std::mem::size_of::<Vertex>() as u64,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Uint32],
                })],
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: Some(wgpu::DepthStencilState {
                format: wgpu::TextureFormat::Depth32Float,
                depth_write_enabled: Some(true),
                depth_compare: Some(wgpu::CompareFunction::Less),
                stencil: Default::default(),
                bias: Default::default(),
            }),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs_camera"),
                compilation_options: Default::default(),
                targets: &[
                    Some(wgpu::TextureFormat::Rgba32Float.into()),
                    Some(wgpu::TextureFormat::R32Uint.into()),
                    Some(wgpu::TextureFormat::Rgba8Unorm.into()),
                    Some(wgpu::TextureFormat::R32Float.into()),
                    Some(wgpu::TextureFormat::Rgba32Float.into()),
                    Some(wgpu::TextureFormat::Rg32Float.into()),
                    Some(wgpu::TextureFormat::Rgba8Unorm.into()),
                ],
            }),
            multiview_mask: None,
            cache: None,
        });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(format!("creating the pipelines on {name}: {e}"));
        }
        Ok(Self {
            device,
            queue,
            name,
            shadow_pipelines,
            camera_pipeline,
            shadow_bgl,
            camera_bgl,
        })
    }

    fn buffer(&self, bytes: &[u8], usage: wgpu::BufferUsages) -> wgpu::Buffer {
        let b = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: (bytes.len() as u64).max(16).next_multiple_of(16),
            usage: usage | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        self.queue.write_buffer(&b, 0, bytes);
        b
    }

    fn vertices(&self, f: &FrameInput) -> wgpu::Buffer {
        let v: Vec<Vertex> = (0..f.positions.len())
            .map(|i| Vertex {
                pos: f.positions[i].as_vec3().to_array(),
                normal: f.normals[i].as_vec3().to_array(),
                id: f.surface[i],
            })
            .collect();
        self.buffer(bytemuck::cast_slice(&v), wgpu::BufferUsages::VERTEX)
    }

    /// Renders the maps into a depth array texture: map i draws the vertex ranges `draws[i]`.
    fn shadow_maps(
        &self,
        enc: &mut wgpu::CommandEncoder,
        vb: &wgpu::Buffer,
        f: &FrameInput,
    ) -> wgpu::Texture {
        let reversed = f.reversed();
        let tex = self.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("shadow maps"),
            size: wgpu::Extent3d {
                width: f.res,
                height: f.res,
                depth_or_array_layers: f.maps.len() as u32,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Depth32Float,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::TEXTURE_BINDING
                | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let pipeline = &self.shadow_pipelines[usize::from(reversed)]
            [usize::from(f.lookup == Lookup::FirstSurface)];
        for (i, m) in f.maps.iter().enumerate() {
            let mut u = m.to_bytes().to_vec();
            u.extend_from_slice(bytemuck::cast_slice(&vec4(
                f.light,
                crate::scene::FACING as f32,
            )));
            u.extend_from_slice(bytemuck::cast_slice(&vec4(f.offset, 0.0)));
            let ub = self.buffer(&u, wgpu::BufferUsages::UNIFORM);
            let bg = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: None,
                layout: &self.shadow_bgl,
                entries: &[wgpu::BindGroupEntry {
                    binding: 0,
                    resource: ub.as_entire_binding(),
                }],
            });
            let view = tex.create_view(&wgpu::TextureViewDescriptor {
                dimension: Some(wgpu::TextureViewDimension::D2),
                base_array_layer: i as u32,
                array_layer_count: Some(1),
                ..Default::default()
            });
            let mut pass = enc.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("shadow"),
                color_attachments: &[],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &view,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(if reversed { 0.0 } else { 1.0 }),
                        store: wgpu::StoreOp::Store,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, &bg, &[]);
            pass.set_vertex_buffer(0, vb.slice(..));
            for r in f.draws.get(i).map_or(&[][..], Vec::as_slice) {
                pass.draw(r.clone(), 0..1);
            }
        }
        tex
    }

    /// The shadow maps alone, read back (for the shimmer test): depth per texel, layer by layer,
    /// rows from the top (t = 1).
    ///
    /// # Errors
    /// A GPU error.
    pub fn render_maps(&self, f: &FrameInput) -> Result<Vec<f32>, String> {
        self.scoped(|| self.render_maps_inner(f))
    }

    /// Runs `f` inside a validation error scope: a wgpu validation error becomes `Err`.
    fn scoped<T>(&self, f: impl FnOnce() -> Result<T, String>) -> Result<T, String> {
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let r = f();
        match pollster::block_on(scope.pop()) {
            Some(e) => Err(format!("GPU validation error on {}: {e}", self.name)),
            None => r,
        }
    }

    fn render_maps_inner(&self, f: &FrameInput) -> Result<Vec<f32>, String> {
        let vb = self.vertices(f);
        let mut enc = self.device.create_command_encoder(&Default::default());
        let tex = self.shadow_maps(&mut enc, &vb, f);
        let layers = f.maps.len() as u32;
        let (buf, row) = self.copy_out(
            &mut enc,
            &tex,
            f.res,
            f.res,
            layers,
            4,
            wgpu::TextureAspect::DepthOnly,
        );
        self.queue.submit([enc.finish()]);
        let bytes = self.read(&buf, row, f.res, f.res, layers, 4)?;
        Ok(bytemuck::cast_slice(&bytes).to_vec())
    }

    /// Shadow maps and the camera pass, read back.
    ///
    /// # Errors
    /// A GPU error.
    pub fn render(&self, f: &FrameInput) -> Result<FrameOutput, String> {
        if f.maps.is_empty() || f.positions.is_empty() {
            return Err("nothing to render (no map or no triangle)".into());
        }
        self.scoped(|| self.render_inner(f))
    }

    fn render_inner(&self, f: &FrameInput) -> Result<FrameOutput, String> {
        let vb = self.vertices(f);
        let mut enc = self.device.create_command_encoder(&Default::default());
        let maps = self.shadow_maps(&mut enc, &vb, f);
        self.queue.submit([enc.finish()]);
        self.camera_pass(
            f,
            &vb,
            &maps,
            &PathPass {
                records: f.maps,
                flags: bias_flags(f.lookup),
                radius: 0,
                lens: true,
            },
        )
    }

    /// The shadow maps once, read back, and one camera pass per entry of `passes`, each with its
    /// own records, `sa_visibility` flags and PCF radius ([`crate::paths`]).
    ///
    /// # Errors
    /// A GPU error; nothing to render; a pass whose records are not one per map.
    pub fn render_paths(
        &self,
        f: &FrameInput,
        passes: &[PathPass],
    ) -> Result<(Vec<f32>, Vec<FrameOutput>), String> {
        if f.maps.is_empty() || f.positions.is_empty() {
            return Err("nothing to render (no map or no triangle)".into());
        }
        if passes.iter().any(|p| p.records.len() != f.maps.len()) {
            return Err("a shader-path pass needs one record per map".into());
        }
        self.scoped(|| {
            let vb = self.vertices(f);
            let mut enc = self.device.create_command_encoder(&Default::default());
            let maps = self.shadow_maps(&mut enc, &vb, f);
            let layers = f.maps.len() as u32;
            let (buf, row) = self.copy_out(
                &mut enc,
                &maps,
                f.res,
                f.res,
                layers,
                4,
                wgpu::TextureAspect::DepthOnly,
            );
            self.queue.submit([enc.finish()]);
            let bytes = self.read(&buf, row, f.res, f.res, layers, 4)?;
            let depth: Vec<f32> = bytemuck::cast_slice(&bytes).to_vec();
            let outs = passes
                .iter()
                .map(|p| self.camera_pass(f, &vb, &maps, p))
                .collect::<Result<Vec<_>, String>>()?;
            Ok((depth, outs))
        })
    }

    /// The camera pass over the rendered `maps` with the pass's records, `sa_visibility` flags and
    /// PCF radius, read back.
    fn camera_pass(
        &self,
        f: &FrameInput,
        vb: &wgpu::Buffer,
        maps: &wgpu::Texture,
        pass: &PathPass,
    ) -> Result<FrameOutput, String> {
        let PathPass {
            records,
            flags,
            radius,
            lens,
        } = *pass;
        let mut enc = self.device.create_command_encoder(&Default::default());
        let maps_view = maps.create_view(&wgpu::TextureViewDescriptor {
            dimension: Some(wgpu::TextureViewDimension::D2Array),
            ..Default::default()
        });
        let globals = GlobalsRaw {
            rel_to_clip: mat(f.rel_to_clip),
            rel_to_eye: mat(f.rel_to_eye),
            light: vec4(f.light, crate::scene::FACING as f32),
            light_eye: vec4(f.light_eye, f.mode as f32),
            frustum: f.frustum.map(|x| x as f32),
            misc: [
                f.res as f32,
                f.maps.len() as f32,
                flags as f32,
                // sa_error_lens's focal_pixels: H / (2 tan θ).
                (f64::from(f.height) / (2.0 * f.frustum[2])) as f32,
            ],
            offset: vec4(f.offset, 0.0),
            clipmap: [
                f.clipmap[0] as f32,
                f.clipmap[1] as f32,
                f.clipmap[2] as f32,
                0.0,
            ],
            faults: [
                f32::from(u8::from(f.one_map_in_band)),
                radius as f32,
                f32::from(u8::from(!lens)),
                0.0,
            ],
        };
        let records: Vec<u8> = records.iter().flat_map(|m| m.to_bytes()).collect();
        let gb = self.buffer(bytemuck::bytes_of(&globals), wgpu::BufferUsages::UNIFORM);
        let pb = self.buffer(&records, wgpu::BufferUsages::STORAGE);
        let bg = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &self.camera_bgl,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: gb.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: pb.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: wgpu::BindingResource::TextureView(&maps_view),
                },
            ],
        });
        let (w, h) = (f.width, f.height);
        let t_texel = self.target(w, h, wgpu::TextureFormat::Rgba32Float);
        let t_id = self.target(w, h, wgpu::TextureFormat::R32Uint);
        let t_color = self.target(w, h, wgpu::TextureFormat::Rgba8Unorm);
        let t_light = self.target(w, h, wgpu::TextureFormat::R32Float);
        let t_blend = self.target(w, h, wgpu::TextureFormat::Rgba32Float);
        let t_lens = self.target(w, h, wgpu::TextureFormat::Rg32Float);
        let t_overlay = self.target(w, h, wgpu::TextureFormat::Rgba8Unorm);
        let t_depth = self.target(w, h, wgpu::TextureFormat::Depth32Float);
        let views = [
            &t_texel, &t_id, &t_color, &t_light, &t_blend, &t_lens, &t_overlay, &t_depth,
        ]
        .map(|t| t.create_view(&Default::default()));
        {
            let clear = |c: wgpu::Color| wgpu::Operations {
                load: wgpu::LoadOp::Clear(c),
                store: wgpu::StoreOp::Store,
            };
            // Targets 0–6 as above; the colour and the overlay (2, 6) cleared to the sky.
            let sky = wgpu::Color {
                r: 0.55,
                g: 0.7,
                b: 0.9,
                a: 1.0,
            };
            let colour: [Option<wgpu::RenderPassColorAttachment>; 7] = std::array::from_fn(|i| {
                Some(wgpu::RenderPassColorAttachment {
                    view: &views[i],
                    depth_slice: None,
                    resolve_target: None,
                    ops: clear(if i == 2 || i == 6 {
                        sky
                    } else {
                        wgpu::Color::TRANSPARENT
                    }),
                })
            });
            let mut pass = enc.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("camera"),
                color_attachments: &colour,
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &views[7],
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(1.0),
                        store: wgpu::StoreOp::Store,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_pipeline(&self.camera_pipeline);
            pass.set_bind_group(0, &bg, &[]);
            pass.set_vertex_buffer(0, vb.slice(..));
            pass.draw(0..f.positions.len() as u32, 0..1);
        }
        let all = wgpu::TextureAspect::All;
        let (b0, r0) = self.copy_out(&mut enc, &t_texel, w, h, 1, 16, all);
        let (b1, r1) = self.copy_out(&mut enc, &t_id, w, h, 1, 4, all);
        let (b2, r2) = self.copy_out(&mut enc, &t_color, w, h, 1, 4, all);
        let (b3, r3) = self.copy_out(&mut enc, &t_light, w, h, 1, 4, all);
        let (b4, r4) = self.copy_out(&mut enc, &t_blend, w, h, 1, 16, all);
        let (b5, r5) = self.copy_out(&mut enc, &t_lens, w, h, 1, 8, all);
        let (b6, r6) = self.copy_out(&mut enc, &t_overlay, w, h, 1, 4, all);
        self.queue.submit([enc.finish()]);
        let texel = self.read(&b0, r0, w, h, 1, 16)?;
        let id = self.read(&b1, r1, w, h, 1, 4)?;
        let color = self.read(&b2, r2, w, h, 1, 4)?;
        let depth = self.read(&b3, r3, w, h, 1, 4)?;
        let blend = self.read(&b4, r4, w, h, 1, 16)?;
        let lens = self.read(&b5, r5, w, h, 1, 8)?;
        let overlay = self.read(&b6, r6, w, h, 1, 4)?;
        Ok(FrameOutput {
            texel: bytemuck::cast_slice(&texel).to_vec(),
            id: bytemuck::cast_slice(&id).to_vec(),
            color: bytemuck::cast_slice(&color).to_vec(),
            depth: bytemuck::cast_slice(&depth).to_vec(),
            blend: bytemuck::cast_slice(&blend).to_vec(),
            lens: bytemuck::cast_slice(&lens).to_vec(),
            overlay: bytemuck::cast_slice(&overlay).to_vec(),
        })
    }
}
