//! A global allocator that staggers where large arrays start within the 4 KiB page.
//!
//! The explicit kernel streams a score of separate `Vec<f64>` (structure of arrays: `x`, `v`, the
//! segments' forces, the masses, ...) through each loop, storing into some while loading from others.
//! A processor checks a load against the older stores still in flight by the low 12 bits of their
//! addresses first ("4K aliasing"): a load whose address matches a pending store's in bits 11..0 but
//! not in full waits as if it depended on it. When the arrays of one loop start at nearly the same
//! offset within the page, loads at index `j` match stores at `j - d` for small `d` every iteration.
//! The system allocator places a run of equal-sized arrays one chunk apart, so the offsets depend on
//! the array length: with 1025 doubles (N = 1024) every chunk is 8208 bytes, 16 bytes past two pages,
//! and all of the arrays start within a few cache lines of each other (figures/bench/README.md, issue
//! 27's seventh round, measured on a Zen 3: 1.8e8 node-steps/s at N = 1024 against 2.4-2.8e8 at N = 1000,
//! 1100, 1500, 2000, and 1.5-1.8e8 at every N when every array is page-aligned;
//! `figures/bench/issue27_r7_page_aligned.log`).
//!
//! [`spread_evenly`] moves a kernel's arrays into fresh allocations; under [`StaggeredAlloc`] the
//! `i`-th of `m` of them then starts `64 floor(64 i / m)` bytes into a page, so no two start within
//! `4096 / m` bytes (about 20 doubles for a wire's 26 arrays) of each other modulo the page, whatever
//! the length, for arrays of at least [`MIN_SIZE`] bytes (32 doubles: N >= 31). Every array so placed
//! also starts a cache line, so the kernel's 512-bit loads and stores at `j` stay within one line (a
//! Zen 5 takes about twice as long over one that crosses two: issue 27's thirteenth round, where placing
//! the arrays of N = 50 and 200 too made the kernel 2-29 % faster; no aliasing was measured for them,
//! whose arrays the system allocator had put next to each other, at 16-byte boundaries). Every other
//! allocation of at least [`MIN_SIZE`] bytes costs 16 bytes of header and keeps the system allocator's
//! place; smaller ones go to the system allocator unchanged. A spread array costs up to 4 KiB of padding.
//! Addresses never enter the arithmetic, so results are bitwise the same with or without it; only the
//! time changes.
//!
//! A binary opts in with
//! ```no_run
//! #[global_allocator]
//! static ALLOC: ohl::staggered_alloc::StaggeredAlloc = ohl::staggered_alloc::StaggeredAlloc;
//! # fn main() {}
//! ```
//! (the `ohl` command, the `verify` harness and the Python extension do).

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// The page whose low address bits the processor compares first [bytes].
pub const PAGE: usize = 4096;
/// The granularity of the offsets (one cache line) [bytes].
pub const GRAIN: usize = 64;
/// The smallest allocation that goes through the header and may be placed [bytes]: 32 doubles (a wire
/// of 31 segments; four lines of 64 bytes). Smaller ones go to the system allocator whole: a page of
/// padding for a few lines would only add pages to the kernel's working set. (2048 bytes until issue
/// 27's thirteenth round, when only aliasing was looked for; see the module docs.)
pub const MIN_SIZE: usize = 256;
/// Room before a placed block for the address and size of the system allocation it sits in [bytes];
/// a multiple of 16, so a block without an offset keeps the system allocator's alignment.
const HEADER: usize = 16;

thread_local! {
    /// An even spread under way on this thread ([`spread_evenly`]): the index of the next array and the
    /// number of arrays; `(0, 0)` when none.
    static SPREAD: Cell<(usize, usize)> = const { Cell::new((0, 0)) };
}

/// The global allocator of this module's doc.
#[derive(Clone, Copy, Debug, Default)]
pub struct StaggeredAlloc;

/// Moves each array into a fresh allocation so that, under [`StaggeredAlloc`], the `i`-th of the `m`
/// arrays starts at `64 floor(64 i / m)` bytes within the page: the arrays of one kernel spread evenly
/// over the page, neighbours `4096 / m` bytes apart (about 20 doubles for a wire's 26 arrays) instead
/// of wherever their lengths and allocation order put them. Contents and lengths are unchanged; under
/// another global allocator it only copies the arrays. Arrays shorter than [`MIN_SIZE`] bytes are left
/// where they are (not copied); the ones moved take the slots `i = 0, 1, ...` in order, so with some
/// skipped the last slots stay free. An array later replaced by a new `Vec` (rather than written in
/// place) loses its place.
pub fn spread_evenly(arrays: &mut [&mut Vec<f64>]) {
    SPREAD.with(|s| s.set((0, arrays.len())));
    for a in arrays.iter_mut() {
        if std::mem::size_of_val(a.as_slice()) < MIN_SIZE {
            continue;
        }
        let mut fresh = Vec::with_capacity(a.len());
        fresh.extend_from_slice(a);
        **a = fresh;
    }
    SPREAD.with(|s| s.set((0, 0)));
}

/// The offset within the page for a large allocation now [bytes]: the next of an even spread under
/// way on this thread, else none (`None`: the block follows its header directly).
#[inline]
fn spread_offset() -> Option<usize> {
    SPREAD
        .try_with(|s| {
            let (i, m) = s.get();
            (m > 0).then(|| {
                s.set((i + 1, m));
                (i % m) * (PAGE / GRAIN) / m * GRAIN
            })
        })
        .ok()
        .flatten()
}

/// Whether an allocation of this layout goes through the header (and may be placed): at least
/// [`MIN_SIZE`] bytes, aligned to at most 16 (what the system allocator gives; a placed block is
/// aligned to [`GRAIN`]).
#[inline]
fn large(layout: Layout) -> bool {
    layout.size() >= MIN_SIZE && layout.align() <= HEADER
}

/// A large block: its system allocation, with the header (that allocation's address and size) in the
/// `HEADER` bytes before the block, and the block at `offset` within the page when one is given.
///
/// # Safety
/// `layout` is large ([`large`]).
unsafe fn alloc_large(layout: Layout, offset: Option<usize>, zeroed: bool) -> *mut u8 {
    let pad = if offset.is_some() { PAGE } else { 0 };
    let Some(size) = layout.size().checked_add(HEADER + pad) else {
        return std::ptr::null_mut();
    };
    let Ok(outer) = Layout::from_size_align(size, HEADER) else {
        return std::ptr::null_mut();
    };
    // SAFETY: `outer` has a non-zero size.
    let raw = unsafe { if zeroed { System.alloc_zeroed(outer) } else { System.alloc(outer) } };
    if raw.is_null() {
        return raw;
    }
    let first = raw as usize + HEADER;
    let shift = match offset {
        Some(target) => HEADER + (target + PAGE - first % PAGE) % PAGE,
        None => HEADER,
    };
    // SAFETY: `shift < HEADER + PAGE` with an offset (`HEADER` without), so the block ends inside
    // `outer`; it is aligned to 16 (a multiple of `GRAIN` when placed), and the header's two words lie
    // inside `outer`, just before the block.
    unsafe {
        let block = raw.add(shift);
        write_header(block, raw, outer.size());
        block
    }
}

/// Writes the header of the large block at `block`: its system allocation `raw` of `size` bytes
/// (aligned to `HEADER`), read back by [`outer_of`].
///
/// # Safety
/// The `HEADER` bytes before `block` lie inside that allocation, and `block` is aligned to 16.
unsafe fn write_header(block: *mut u8, raw: *mut u8, size: usize) {
    // SAFETY: the two words before `block`, inside the allocation (the caller's contract).
    unsafe {
        let header = block.cast::<usize>().sub(2);
        header.write(raw as usize);
        header.add(1).write(size);
    }
}

/// The system allocation of a large block (from its header).
///
/// # Safety
/// `ptr` is a large block of this allocator ([`alloc_large`], or grown in place by `realloc`), not freed.
unsafe fn outer_of(ptr: *mut u8) -> (*mut u8, Layout) {
    // SAFETY: the header written by `write_header` for `alloc_large` or `realloc`.
    unsafe {
        let header = ptr.cast::<usize>().sub(2);
        let raw = header.read() as *mut u8;
        (raw, Layout::from_size_align_unchecked(header.add(1).read(), HEADER))
    }
}

// SAFETY: every large block lies inside its own system allocation, after the header that names it;
// `dealloc` and `realloc` receive the layout `alloc` was given (the `GlobalAlloc` contract), so `large`
// decides the same way both times and a block with a header is always freed through it.
unsafe impl GlobalAlloc for StaggeredAlloc {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if !large(layout) {
            // SAFETY: the caller's contract, passed on.
            return unsafe { System.alloc(layout) };
        }
        // SAFETY: a large layout.
        unsafe { alloc_large(layout, spread_offset(), false) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        if !large(layout) {
            // SAFETY: the caller's contract, passed on.
            return unsafe { System.alloc_zeroed(layout) };
        }
        // SAFETY: a large layout.
        unsafe { alloc_large(layout, spread_offset(), true) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        if !large(layout) {
            // SAFETY: a system block of this layout (the same decision in `alloc`).
            return unsafe { System.dealloc(ptr, layout) };
        }
        // SAFETY: a large block: freed through its header.
        unsafe {
            let (raw, outer) = outer_of(ptr);
            System.dealloc(raw, outer);
        }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: the caller's contract: `new_size` is non-zero and valid for `layout.align()`.
        let new_layout = unsafe { Layout::from_size_align_unchecked(new_size, layout.align()) };
        if !large(layout) && !large(new_layout) {
            // SAFETY: a system block of `layout` that stays one.
            return unsafe { System.realloc(ptr, layout, new_size) };
        }
        if large(layout) && large(new_layout) {
            // SAFETY: a large block: its header names its system allocation.
            let (raw, outer) = unsafe { outer_of(ptr) };
            if ptr as usize - raw as usize == HEADER {
                // Not placed (the block follows its header): the system allocation grows or shrinks with
                // it, header and all, and the header is written again for the new one.
                let Some(size) = new_size.checked_add(HEADER) else { return std::ptr::null_mut() };
                // SAFETY: `raw` was allocated by `System` with `outer`; `size` is non-zero and, with
                // `outer`'s alignment, a valid layout (checked above for overflow; far below `isize::MAX`
                // for any allocation that succeeds).
                unsafe {
                    let grown = System.realloc(raw, outer, size);
                    if grown.is_null() {
                        return grown;
                    }
                    let block = grown.add(HEADER);
                    write_header(block, grown, size);
                    return block;
                }
            }
        }
        // SAFETY: a new block of the new layout (never placed: growth is not a kernel's array), the
        // common prefix copied, the old block freed with its own layout.
        unsafe {
            let block = if large(new_layout) { alloc_large(new_layout, None, false) } else { System.alloc(new_layout) };
            if !block.is_null() {
                std::ptr::copy_nonoverlapping(ptr, block, layout.size().min(new_size));
                self.dealloc(ptr, layout);
            }
            block
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Under a spread, the `m` large blocks start at `64 floor(64 i / m)` within the page, in order; a
    /// block made outside a spread is not placed (it follows its header). Contents are written to the
    /// whole of each block and the blocks freed through the allocator (a wrong header would free the
    /// wrong system block, which the system allocator reports or the next test run would crash on).
    #[test]
    fn spread_blocks_start_evenly_over_the_page() {
        let a = StaggeredAlloc;
        let m = 26;
        let layout = Layout::array::<f64>(1025).unwrap();
        SPREAD.with(|s| s.set((0, m)));
        // SAFETY: non-zero layouts; each block written within its size and freed with its layout.
        let blocks: Vec<*mut u8> = (0..m).map(|_| unsafe { a.alloc(layout) }).collect();
        SPREAD.with(|s| s.set((0, 0)));
        for (i, &p) in blocks.iter().enumerate() {
            assert!(!p.is_null());
            assert_eq!(p as usize % PAGE, 64 * (64 * i / m), "array {i}");
            // SAFETY: as above.
            unsafe { p.write_bytes(i as u8, layout.size()) };
        }
        for (i, &p) in blocks.iter().enumerate() {
            // SAFETY: as above; every other block is grown first (a placed block moves to a plain one).
            unsafe {
                assert!(std::slice::from_raw_parts(p, layout.size()).iter().all(|&b| b == i as u8));
                if i % 2 == 0 {
                    a.dealloc(p, layout);
                } else {
                    let q = a.realloc(p, layout, 3 * layout.size());
                    assert!(std::slice::from_raw_parts(q, layout.size()).iter().all(|&b| b == i as u8));
                    a.dealloc(q, Layout::array::<f64>(3 * 1025).unwrap());
                }
            }
        }
        // SAFETY: as above.
        unsafe {
            let p = a.alloc(layout);
            let (raw, outer) = outer_of(p);
            assert_eq!(p as usize - raw as usize, HEADER);
            assert_eq!(outer.size(), layout.size() + HEADER);
            a.dealloc(p, layout);
        }
    }

    /// Blocks of every class around the threshold: the alignment asked, zeroed when asked, contents kept
    /// through `realloc` across the threshold both ways and within the large class (the system's
    /// `realloc` under the header).
    #[test]
    fn blocks_are_aligned_and_round_trip() {
        let a = StaggeredAlloc;
        for &(size, align) in
            &[(8, 8), (MIN_SIZE - 1, 8), (MIN_SIZE, 8), (8200, 8), (40_000, 16), (4000, 64), (4000, 128)]
        {
            let layout = Layout::from_size_align(size, align).unwrap();
            // SAFETY: non-zero layouts; blocks written within their sizes and freed with their layouts.
            unsafe {
                let p = a.alloc_zeroed(layout);
                assert!(!p.is_null());
                assert_eq!(p as usize % align, 0, "size {size} align {align}");
                assert!(std::slice::from_raw_parts(p, size).iter().all(|&b| b == 0));
                a.dealloc(p, layout);
                for &new_size in &[size / 2 + 1, size * 3, 100, 2500, 100_000] {
                    let p = a.alloc(layout);
                    for i in 0..size {
                        p.add(i).write((i % 251) as u8);
                    }
                    let q = a.realloc(p, layout, new_size);
                    assert!(!q.is_null());
                    assert_eq!(q as usize % align, 0);
                    let kept = size.min(new_size);
                    assert!((0..kept).all(|i| q.add(i).read() == (i % 251) as u8), "{size} -> {new_size}");
                    a.dealloc(q, Layout::from_size_align(new_size, align).unwrap());
                }
            }
        }
    }
}
