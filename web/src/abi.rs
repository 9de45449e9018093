//! The module's four exports over linear memory, for web/npm/index.js:
//!
//! 1. `saw_alloc(len)` gives a buffer of `len` bytes; JavaScript writes the request's UTF-8
//!    into it;
//! 2. `saw_call(ptr, len)` takes the buffer back (freeing it), answers the request
//!    ([`crate::call`]) and returns 0 (an answer) or 1 (an error);
//! 3. `saw_out_ptr()` and `saw_out_len()` locate the answer's UTF-8, valid until the next call.

use std::cell::RefCell;

thread_local! {
    /// The last answer.
    static OUT: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
}

/// A buffer of `len` zero bytes for the caller to fill; `saw_call` frees it.
#[no_mangle]
pub extern "C" fn saw_alloc(len: usize) -> *mut u8 {
    Box::into_raw(vec![0u8; len].into_boxed_slice()).cast::<u8>()
}

/// Answers the request in the buffer `ptr` of `len` bytes that `saw_alloc(len)` gave (freed
/// here): 0 with the answer, 1 with an error (`saw_out_ptr`, `saw_out_len`).
///
/// # Safety
/// `ptr` and `len` must be a buffer from `saw_alloc(len)`, not used again.
#[no_mangle]
pub unsafe extern "C" fn saw_call(ptr: *mut u8, len: usize) -> u32 {
    // SAFETY: the caller passes back a `Box<[u8]>` of `len` bytes that saw_alloc leaked.
    let bytes = unsafe { Box::from_raw(std::ptr::slice_from_raw_parts_mut(ptr, len)) };
    let (status, answer) = match std::str::from_utf8(&bytes) {
        Ok(s) => match crate::call(s) {
            Ok(a) => (0, a),
            Err(e) => (1, e),
        },
        Err(_) => (
            1,
            crate::args::WebError::request("the request is not UTF-8").to_json(),
        ),
    };
    OUT.with_borrow_mut(|o| {
        o.clear();
        o.extend_from_slice(answer.as_bytes());
    });
    status
}

/// Where the last answer starts.
#[no_mangle]
pub extern "C" fn saw_out_ptr() -> *const u8 {
    OUT.with_borrow(|o| o.as_ptr())
}

/// The last answer's length in bytes.
#[no_mangle]
pub extern "C" fn saw_out_len() -> usize {
    OUT.with_borrow(|o| o.len())
}
