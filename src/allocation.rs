//! Fallible allocation of the large buffers (films, their splat sums): a
//! request the system refuses (`ulimit -v`, a budget raised past the
//! machine's memory) is an error with the size and what it was for, never
//! an abort that leaves the outputs' temporaries behind.
//!
//! [`check_available`] asks the system once for a render's peak memory
//! before the render starts (the address space is reserved and given back
//! at once, never touched), so that the later allocations of the image and
//! its encoding, which go through crates that cannot fail softly, are
//! known to fit; [`filled`] allocates a buffer with `try_reserve_exact`.

use crate::limits::show_bytes;

/// The error of a refused allocation of `bytes` for `what`.
fn refused(bytes: u64, what: &str) -> String {
    format!(
        "cannot allocate {} for {what}: the system refused the memory (see `ulimit -v`, \
         or lower --max-memory, the image size or the thread count)",
        show_bytes(bytes)
    )
}

/// Checks that the system grants `bytes` of memory now, for `what`.
pub fn check_available(bytes: u64, what: &str) -> Result<(), String> {
    let Ok(length) = usize::try_from(bytes) else {
        return Err(refused(bytes, what));
    };
    let mut probe: Vec<u8> = Vec::new();
    probe
        .try_reserve_exact(length)
        .map_err(|_| refused(bytes, what))
}

/// A vector of `length` copies of `value`, or an error naming `what` if the
/// system refuses the memory.
pub fn filled<T: Clone>(length: usize, value: T, what: &str) -> Result<Vec<T>, String> {
    let bytes = (length as u64).saturating_mul(std::mem::size_of::<T>() as u64);
    let mut buffer: Vec<T> = Vec::new();
    buffer
        .try_reserve_exact(length)
        .map_err(|_| refused(bytes, what))?;
    buffer.resize(length, value);
    Ok(buffer)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_impossible_request_is_an_error_naming_its_size() {
        let error = check_available(u64::MAX / 2, "a test").unwrap_err();
        assert!(error.contains("EiB") || error.contains("TiB"), "{error}");
        assert!(error.contains("a test"), "{error}");
        let error = filled(usize::MAX / 16, 0u64, "a film").unwrap_err();
        assert!(error.contains("a film"), "{error}");
        assert_eq!(filled(3, 7u8, "small").unwrap(), [7, 7, 7]);
        assert!(check_available(1 << 20, "a mebibyte").is_ok());
    }
}
