//! A pseudo-random sequence for the unit tests: Marsaglia's xorshift64 (shifts 13, 7, 17), reproducible
//! from its seed without a crate. The tests that compare a fast path with the code it replaces, or a
//! formula with brute force, draw their points from it.

/// Uniform numbers in `[0, 1)` from a nonzero `seed`: the top 53 bits of each state over `2^53`.
pub(crate) fn uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Uniform numbers in `[-1, 1)`: [`uniform`]'s, times 2, minus 1.
pub(crate) fn symmetric(seed: u64) -> impl FnMut() -> f64 {
    let mut u = uniform(seed);
    move || u() * 2.0 - 1.0
}
