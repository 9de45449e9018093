//! A backend that draws nothing: a chart is laid out on it first to learn where its data fall
//! (a legend's free spot, say) before it is drawn for real on the same size.

use super::super::canvas::{Canvas, BITMAP_TEXT};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters_backend::{BackendColor, BackendCoord, DrawingErrorKind};

/// A page of `size` units on which every drawing call succeeds and leaves nothing.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Probe {
    size: (u32, u32),
}

impl DrawingBackend for Probe {
    type ErrorType = std::fmt::Error;

    fn get_size(&self) -> (u32, u32) {
        self.size
    }

    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        Ok(())
    }

    fn present(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        Ok(())
    }

    fn draw_pixel(
        &mut self,
        _: BackendCoord,
        _: BackendColor,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        Ok(())
    }
}

/// A drawing area of `size` units over [`Probe`], measuring text as every figure's canvas does
/// ([`Canvas`] measures its text itself, whatever it draws on).
pub(crate) fn probe_area(size: (u32, u32)) -> DrawingArea<Canvas<Probe>, Shift> {
    Canvas::new(Probe { size }, 1, BITMAP_TEXT).into_drawing_area()
}
