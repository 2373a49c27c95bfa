//! Criterion timings on a CPU clock rather than the wall: these machines
//! are shared, and a thread's (or the process's) CPU time is what the code
//! itself spends. Shared by the benches through `#[path]`.

use std::hint::black_box;
use std::time::Duration;

/// The CPU time of `clock` (a `CLOCK_*_CPUTIME_ID`).
fn now(clock: libc::clockid_t) -> Duration {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: a valid pointer to a timespec; the clock id is a constant.
    unsafe { libc::clock_gettime(clock, &mut t) };
    Duration::new(t.tv_sec as u64, t.tv_nsec as u32)
}

fn timed<O>(b: &mut criterion::Bencher, clock: libc::clockid_t, mut f: impl FnMut() -> O) {
    b.iter_custom(|iters| {
        let start = now(clock);
        for _ in 0..iters {
            black_box(f());
        }
        now(clock) - start
    })
}

/// `b.iter(f)` timed on this thread's CPU clock.
pub fn cpu_iter<O>(b: &mut criterion::Bencher, f: impl FnMut() -> O) {
    timed(b, libc::CLOCK_THREAD_CPUTIME_ID, f)
}

/// `b.iter(f)` timed on the process's CPU clock: every thread's time
/// (`assess` runs two).
#[allow(dead_code)]
pub fn process_cpu_iter<O>(b: &mut criterion::Bencher, f: impl FnMut() -> O) {
    timed(b, libc::CLOCK_PROCESS_CPUTIME_ID, f)
}
