//! Storage for the large arrays that ray queries read at random (BVH nodes,
//! packed mesh triangles): on Linux, anonymous memory advised for
//! transparent huge pages, so that one TLB entry covers 2 MiB instead of
//! 4 KiB. Systems whose huge pages are set to `madvise`
//! (`/sys/kernel/mm/transparent_hugepage/enabled`, as on the machine of the
//! figures of docs/guide/performance.md) give them only to memory that asks; a query through a
//! large mesh otherwise pays a page walk on most node and triangle reads.
//!
//! Small arrays, other systems and a failed mapping use a plain `Vec`: the
//! contents are the same either way, only where they live differs.

use bytemuck::Pod;

/// Arrays smaller than this stay on the heap (a huge page is 2 MiB).
const MIN_MAPPED_BYTES: usize = 2 << 20;

/// A fixed-length array of plain values.
pub struct HugeArray<T: Pod> {
    storage: Storage<T>,
}

enum Storage<T> {
    Heap(Vec<T>),
    #[cfg(target_os = "linux")]
    Mapped {
        map: memmap2::MmapMut,
        len: usize,
    },
}

impl<T: Pod> HugeArray<T> {
    /// The values of `values`, in huge pages when they are large enough.
    pub fn from_slice(values: &[T]) -> HugeArray<T>
    where
        T: Send + Sync,
    {
        HugeArray::from_fn(values.len(), |i| values[i])
    }

    /// `value(i)` for each `i < len`, computed in parallel (rayon) and
    /// written in place (no copy of a large array through the heap), each
    /// to its own place, so the array is the same for any number of
    /// threads.
    pub fn from_fn(len: usize, value: impl Fn(usize) -> T + Sync) -> HugeArray<T>
    where
        T: Send,
    {
        use rayon::prelude::*;
        const CHUNK: usize = 4096;
        let fill = |values: &mut [T]| {
            values
                .par_chunks_mut(CHUNK)
                .enumerate()
                .for_each(|(c, chunk)| {
                    for (i, v) in chunk.iter_mut().enumerate() {
                        *v = value(c * CHUNK + i);
                    }
                });
        };
        #[cfg(target_os = "linux")]
        if let Some(mut map) = Self::map(len) {
            fill(bytemuck::cast_slice_mut(&mut map[..]));
            return HugeArray {
                storage: Storage::Mapped { map, len },
            };
        }
        let mut values = vec![T::zeroed(); len];
        fill(&mut values);
        HugeArray {
            storage: Storage::Heap(values),
        }
    }

    /// An anonymous mapping for `len` values, advised for huge pages, when
    /// they are large enough to fill one.
    #[cfg(target_os = "linux")]
    fn map(len: usize) -> Option<memmap2::MmapMut> {
        let bytes = len.checked_mul(std::mem::size_of::<T>())?;
        // Mappings are page-aligned; a type aligned beyond a page is not.
        if bytes < MIN_MAPPED_BYTES || std::mem::align_of::<T>() > 4096 {
            return None;
        }
        let map = memmap2::MmapMut::map_anon(bytes).ok()?;
        // Advice before the first touch, so that the pages are huge from
        // the start. Only a request: without it the mapping still works.
        let _ = map.advise(memmap2::Advice::HugePage);
        Some(map)
    }

    pub fn as_slice(&self) -> &[T] {
        match &self.storage {
            Storage::Heap(values) => values,
            #[cfg(target_os = "linux")]
            Storage::Mapped { map, len } => &bytemuck::cast_slice(map)[..*len],
        }
    }

    /// Whether the values live in their own mapping (tests, reports).
    pub fn is_mapped(&self) -> bool {
        !matches!(self.storage, Storage::Heap(_))
    }
}

impl<T: Pod> std::ops::Deref for HugeArray<T> {
    type Target = [T];

    #[inline]
    fn deref(&self) -> &[T] {
        self.as_slice()
    }
}

impl<T: Pod> Default for HugeArray<T> {
    fn default() -> Self {
        HugeArray {
            storage: Storage::Heap(Vec::new()),
        }
    }
}

impl<T: Pod + Send + Sync> Clone for HugeArray<T> {
    fn clone(&self) -> Self {
        HugeArray::from_slice(self.as_slice())
    }
}

impl<T: Pod + std::fmt::Debug> std::fmt::Debug for HugeArray<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("HugeArray")
            .field("len", &self.as_slice().len())
            .field("mapped", &self.is_mapped())
            .finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_and_large_arrays_hold_their_values() {
        for len in [0usize, 3, 1 << 20] {
            let values: Vec<u64> = (0..len as u64).map(|i| i * 7 + 1).collect();
            let array = HugeArray::from_slice(&values);
            assert_eq!(array.as_slice(), &values[..]);
            assert_eq!(array.clone().as_slice(), &values[..]);
            assert_eq!(
                array.is_mapped(),
                cfg!(target_os = "linux") && len == 1 << 20
            );
        }
    }

    #[test]
    fn parallel_fill_puts_every_value_in_its_place() {
        // Lengths that are not multiples of the chunk, on the heap and mapped.
        for len in [0usize, 5, 4097, (1 << 20) + 3] {
            let value = |i: usize| (i as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15);
            let array = HugeArray::from_fn(len, value);
            let expected: Vec<u64> = (0..len).map(value).collect();
            assert_eq!(array.as_slice(), &expected[..]);
            assert_eq!(
                array.is_mapped(),
                cfg!(target_os = "linux") && len > 1 << 20
            );
        }
    }
}
