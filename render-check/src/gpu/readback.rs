//! Render targets and their read-back: a texture to render into, its copy into a mappable
//! buffer (rows padded to 256 bytes), and the buffer mapped and unpadded on the CPU.

use super::Gpu;

impl Gpu {
    /// A 2D render target of `w` × `h` texels in `format` that can be copied out.
    pub(super) fn target(&self, w: u32, h: u32, format: wgpu::TextureFormat) -> wgpu::Texture {
        self.device.create_texture(&wgpu::TextureDescriptor {
            label: None,
            size: wgpu::Extent3d {
                width: w,
                height: h,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        })
    }

    /// Copies `layers` of a texture (`bpp` bytes per texel) into a buffer, rows padded to 256.
    #[allow(clippy::too_many_arguments)] // a texture copy's parameters
    pub(super) fn copy_out(
        &self,
        enc: &mut wgpu::CommandEncoder,
        tex: &wgpu::Texture,
        w: u32,
        h: u32,
        layers: u32,
        bpp: u32,
        aspect: wgpu::TextureAspect,
    ) -> (wgpu::Buffer, u32) {
        let row = (w * bpp).next_multiple_of(256);
        let buf = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: u64::from(row) * u64::from(h) * u64::from(layers),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        enc.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: tex,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &buf,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(row),
                    rows_per_image: Some(h),
                },
            },
            wgpu::Extent3d {
                width: w,
                height: h,
                depth_or_array_layers: layers,
            },
        );
        (buf, row)
    }

    pub(super) fn read(
        &self,
        buf: &wgpu::Buffer,
        row: u32,
        w: u32,
        h: u32,
        layers: u32,
        bpp: u32,
    ) -> Result<Vec<u8>, String> {
        let slice = buf.slice(..);
        slice.map_async(wgpu::MapMode::Read, |_| {});
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| format!("waiting for the GPU: {e}"))?;
        let data = slice
            .get_mapped_range()
            .map_err(|e| format!("reading back: {e}"))?;
        let mut out = Vec::with_capacity((w * h * layers * bpp) as usize);
        for r in 0..(h * layers) as usize {
            let start = r * row as usize;
            out.extend_from_slice(&data[start..start + (w * bpp) as usize]);
        }
        drop(data);
        buf.unmap();
        Ok(out)
    }
}
