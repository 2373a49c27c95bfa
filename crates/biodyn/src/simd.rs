//! SIMD chosen once, in one place. A hot loop is written once, in plain
//! Rust, and [`simd_fn!`] compiles it through `multiversion` for baseline
//! x86-64 and for x86-64 with AVX2 and FMA; the first call picks the clone
//! this CPU runs and remembers it (an atomic function pointer), so no loop
//! checks the CPU again. Rust never fuses a multiply and an add on its own,
//! and `mul_add` is correctly rounded with or without FMA hardware, so both
//! clones give the same bits: the choice changes speed only.
//!
//! A clone may go further with intrinsics where the compiler's own
//! vectorisation falls short: `multiversion::target::match_target!` inside
//! the function picks the hand-written arm in the AVX2 clone only (see
//! `time::kernel`).

/// Puts the crate's SIMD targets on a free function (`multiversion` takes
/// no `self`: a method hands its body to one of these).
macro_rules! simd_fn {
    ($(#[$attr:meta])* $vis:vis fn $($rest:tt)*) => {
        $(#[$attr])*
        #[multiversion::multiversion(targets("x86_64+avx2+fma"))]
        $vis fn $($rest)*
    };
}

pub(crate) use simd_fn;
