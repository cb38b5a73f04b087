//! Acceleration structures for ray queries.

pub mod bvh;
pub mod huge_pages;
pub mod triangles;

pub use bvh::Bvh;
pub use triangles::LeafTriangles;

/// Starts reading every cache line of `value` (a hint: it changes nothing
/// but speed, and does nothing where the target has no prefetch
/// instruction). A value aligned to cache lines fills whole lines; any
/// other may begin inside one and end inside one more.
#[inline(always)]
pub(crate) fn prefetch<T: bytemuck::Pod>(value: &T) {
    #[cfg(target_arch = "x86_64")]
    {
        let bytes: &[u8] = bytemuck::bytes_of(value);
        for offset in (0..bytes.len()).step_by(64) {
            safe_arch::prefetch_t0(&bytes[offset]);
        }
        if !std::mem::align_of::<T>().is_multiple_of(64)
            && let Some(last) = bytes.last()
        {
            safe_arch::prefetch_t0(last);
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = value;
}
