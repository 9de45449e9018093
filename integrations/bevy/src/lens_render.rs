//! The error lens's render-world pass (docs/bevy.md, "The error lens"): a full-screen pass in
//! Bevy's `Core3d` schedule, in `Core3dSystems::PostProcess` after `tonemapping`, reading the
//! view's depth and normal prepass and Bevy's view uniform, and the camera's [`ErrorLensMaps`]
//! as a uniform block; the shader is src/lens.wgsl with the crate's WGSL module
//! (`shadow_aliasing::frame::SHADOW_WGSL`).

use crate::lens::ErrorLensMaps;
use bevy::asset::{Assets, Handle};
use bevy::core_pipeline::prepass::ViewPrepassTextures;
use bevy::core_pipeline::schedule::Core3d;
use bevy::core_pipeline::tonemapping::tonemapping;
use bevy::core_pipeline::{Core3dSystems, FullscreenShader};
use bevy::platform::collections::HashMap;
use bevy::prelude::*;
use bevy::render::extract_component::ExtractComponentPlugin;
use bevy::render::render_resource::binding_types::{
    texture_2d, texture_2d_multisampled, texture_depth_2d, texture_depth_2d_multisampled,
    uniform_buffer, uniform_buffer_sized,
};
use bevy::render::render_resource::{
    BindGroupEntries, BindGroupLayoutDescriptor, BindGroupLayoutEntries, Buffer,
    BufferInitDescriptor, BufferUsages, CachedRenderPipelineId, ColorTargetState, ColorWrites,
    FragmentState, Operations, PipelineCache, RenderPassColorAttachment, RenderPassDescriptor,
    RenderPipelineDescriptor, ShaderStages, TextureFormat, TextureSampleType,
};
use bevy::render::renderer::{RenderContext, RenderDevice, RenderQueue, ViewQuery};
use bevy::render::view::{
    ExtractedView, Msaa, ViewTarget, ViewUniform, ViewUniformOffset, ViewUniforms,
};
use bevy::render::{Render, RenderApp, RenderStartup, RenderSystems};
use bevy::shader::{Shader, ShaderDefVal};
use std::num::NonZeroU64;

/// The lens shader's text: Bevy's imports, the crate's WGSL module, src/lens.wgsl.
fn shader_source() -> String {
    format!(
        "#import bevy_render::view::View\n\
         #import bevy_core_pipeline::fullscreen_vertex_shader::FullscreenVertexOutput\n\
         {}\n{}",
        shadow_aliasing::frame::SHADOW_WGSL,
        include_str!("lens.wgsl")
    )
}

/// Adds the lens's extraction and render-world pass (a no-op without a renderer).
pub(crate) struct ErrorLensRenderPlugin;

impl Plugin for ErrorLensRenderPlugin {
    fn build(&self, app: &mut App) {
        // Without a renderer there is nothing to extract to (and the extraction's removal hook
        // needs the render world's sync resource).
        if app.get_sub_app(RenderApp).is_none() {
            return;
        }
        app.add_plugins(ExtractComponentPlugin::<ErrorLensMaps>::default());
        let Some(render_app) = app.get_sub_app_mut(RenderApp) else {
            return;
        };
        render_app
            .add_systems(RenderStartup, init_pipeline)
            .add_systems(
                Render,
                (
                    prepare_pipelines.in_set(RenderSystems::Prepare),
                    prepare_buffers.in_set(RenderSystems::PrepareResources),
                ),
            )
            .add_systems(
                Core3d,
                error_lens_pass
                    .in_set(Core3dSystems::PostProcess)
                    .after(tonemapping),
            );
    }

    fn finish(&self, app: &mut App) {
        if app.get_sub_app(RenderApp).is_none() {
            return;
        }
        let Some(mut shaders) = app.world_mut().get_resource_mut::<Assets<Shader>>() else {
            return;
        };
        let handle = shaders.add(Shader::from_wgsl(
            shader_source(),
            "shadow_aliasing_bevy/lens.wgsl",
        ));
        if let Some(render_app) = app.get_sub_app_mut(RenderApp) {
            render_app.insert_resource(LensShader(handle));
        }
    }
}

#[derive(Resource)]
struct LensShader(Handle<Shader>);

/// The bind group layouts (single-sampled and multisampled prepass) and the pipelines made so
/// far, by target format and multisampling.
#[derive(Resource)]
struct LensPipeline {
    layouts: [BindGroupLayoutDescriptor; 2],
    shader: Handle<Shader>,
    ids: HashMap<(TextureFormat, bool), CachedRenderPipelineId>,
}

/// The view's pipeline and whether its prepass is multisampled.
#[derive(Component)]
struct LensPipelineId(CachedRenderPipelineId, bool);

/// The view's uniform block ([`ErrorLensMaps::uniform_bytes`]).
#[derive(Component)]
struct LensBuffer(Buffer);

fn layout(multisampled: bool) -> BindGroupLayoutDescriptor {
    let float = TextureSampleType::Float { filterable: false };
    let size = NonZeroU64::new(ErrorLensMaps::UNIFORM_SIZE as u64);
    let entries = if multisampled {
        BindGroupLayoutEntries::sequential(
            ShaderStages::FRAGMENT,
            (
                texture_2d(float),
                texture_depth_2d_multisampled(),
                texture_2d_multisampled(float),
                uniform_buffer::<ViewUniform>(true),
                uniform_buffer_sized(false, size),
            ),
        )
    } else {
        BindGroupLayoutEntries::sequential(
            ShaderStages::FRAGMENT,
            (
                texture_2d(float),
                texture_depth_2d(),
                texture_2d(float),
                uniform_buffer::<ViewUniform>(true),
                uniform_buffer_sized(false, size),
            ),
        )
    };
    BindGroupLayoutDescriptor::new("shadow_aliasing_error_lens", &entries)
}

fn init_pipeline(mut commands: Commands, shader: Res<LensShader>) {
    commands.insert_resource(LensPipeline {
        layouts: [layout(false), layout(true)],
        shader: shader.0.clone(),
        ids: HashMap::default(),
    });
}

fn prepare_pipelines(
    mut commands: Commands,
    cache: Res<PipelineCache>,
    fullscreen: Res<FullscreenShader>,
    mut pipeline: ResMut<LensPipeline>,
    views: Query<(Entity, &ExtractedView, &Msaa), With<ErrorLensMaps>>,
) {
    for (entity, view, msaa) in &views {
        let multisampled = msaa.samples() > 1;
        let key = (view.target_format, multisampled);
        let layout = pipeline.layouts[usize::from(multisampled)].clone();
        let shader = pipeline.shader.clone();
        let id = *pipeline.ids.entry(key).or_insert_with(|| {
            let shader_defs: Vec<ShaderDefVal> = if multisampled {
                vec!["MULTISAMPLED".into()]
            } else {
                Vec::new()
            };
            cache.queue_render_pipeline(RenderPipelineDescriptor {
                label: Some("shadow_aliasing_error_lens".into()),
                layout: vec![layout],
                vertex: fullscreen.to_vertex_state(),
                fragment: Some(FragmentState {
                    shader,
                    shader_defs,
                    targets: vec![Some(ColorTargetState {
                        format: key.0,
                        blend: None,
                        write_mask: ColorWrites::ALL,
                    })],
                    ..default()
                }),
                ..default()
            })
        });
        commands
            .entity(entity)
            .insert(LensPipelineId(id, multisampled));
    }
}

fn prepare_buffers(
    mut commands: Commands,
    device: Res<RenderDevice>,
    queue: Res<RenderQueue>,
    views: Query<(Entity, &ErrorLensMaps, Option<&LensBuffer>)>,
) {
    for (entity, maps, buffer) in &views {
        let bytes = maps.uniform_bytes();
        match buffer {
            Some(b) => queue.write_buffer(&b.0, 0, &bytes),
            None => {
                let b = device.create_buffer_with_data(&BufferInitDescriptor {
                    label: Some("shadow_aliasing_error_lens"),
                    contents: &bytes,
                    usage: BufferUsages::UNIFORM | BufferUsages::COPY_DST,
                });
                commands.entity(entity).insert(LensBuffer(b));
            }
        }
    }
}

#[allow(clippy::type_complexity)]
fn error_lens_pass(
    view: ViewQuery<
        (
            &ViewTarget,
            &ViewPrepassTextures,
            &ViewUniformOffset,
            &LensPipelineId,
            &LensBuffer,
        ),
        With<ErrorLensMaps>,
    >,
    pipeline: Option<Res<LensPipeline>>,
    cache: Res<PipelineCache>,
    view_uniforms: Res<ViewUniforms>,
    mut ctx: RenderContext,
) {
    let (target, prepass, offset, id, buffer) = view.into_inner();
    let (Some(pipeline), Some(render_pipeline), Some(view_binding), Some(depth), Some(normal)) = (
        pipeline,
        cache.get_render_pipeline(id.0),
        view_uniforms.uniforms.binding(),
        prepass.depth_view(),
        prepass.normal_view(),
    ) else {
        return;
    };
    let post_process = target.post_process_write();
    let bind_group = ctx.render_device().create_bind_group(
        "shadow_aliasing_error_lens",
        &cache.get_bind_group_layout(&pipeline.layouts[usize::from(id.1)]),
        &BindGroupEntries::sequential((
            post_process.source,
            depth,
            normal,
            view_binding,
            buffer.0.as_entire_binding(),
        )),
    );
    let mut pass = ctx
        .command_encoder()
        .begin_render_pass(&RenderPassDescriptor {
            label: Some("shadow_aliasing_error_lens"),
            color_attachments: &[Some(RenderPassColorAttachment {
                view: post_process.destination,
                depth_slice: None,
                resolve_target: None,
                ops: Operations::default(),
            })],
            depth_stencil_attachment: None,
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
    pass.set_pipeline(render_pipeline);
    pass.set_bind_group(0, &bind_group, &[offset.offset]);
    pass.draw(0..3, 0..1);
}
