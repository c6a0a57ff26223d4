//! CPU time of the calling thread, for a run's throughput that does not depend on the machine's load:
//! a run's time loop runs on one thread, and the thread's CPU time counts only the time it was given a
//! processor (user and system), where wall time also counts the time it waited for one while other
//! processes ran. Read with `clock_gettime(CLOCK_THREAD_CPUTIME_ID)` (POSIX.1-2001, "Clocks and
//! Timers"; nanosecond resolution on Linux); per thread rather than per process, so that the runs of a
//! parallel sweep each measure their own. Not available off Unix: `None`.

/// The calling thread's CPU time so far [s], or `None` where the system does not provide it.
pub fn thread_cpu_time_s() -> Option<f64> {
    #[cfg(unix)]
    {
        let mut t = libc::timespec { tv_sec: 0, tv_nsec: 0 };
        // SAFETY: `t` is a valid, writable timespec; the call writes only into it.
        let rc = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) };
        (rc == 0).then_some(t.tv_sec as f64 + 1e-9 * t.tv_nsec as f64)
    }
    #[cfg(not(unix))]
    {
        None
    }
}

/// A stopwatch of the calling thread's CPU time.
#[derive(Clone, Copy, Debug)]
pub struct CpuStopwatch(Option<f64>);

impl CpuStopwatch {
    /// Start it now.
    pub fn start() -> Self {
        CpuStopwatch(thread_cpu_time_s())
    }

    /// CPU time of this thread since [`CpuStopwatch::start`] [s] (`None` without a thread clock).
    pub fn elapsed_s(&self) -> Option<f64> {
        Some(thread_cpu_time_s()? - self.0?)
    }
}

/// Throughput `work / seconds` [1/s], 0 for no time (a run too short for the clock).
pub fn per_second(work: f64, seconds: f64) -> f64 {
    if seconds > 0.0 { work / seconds } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The thread's CPU time grows by about the time spent computing, and not while it sleeps: a busy
    /// loop of 0.05 s wall on an otherwise idle thread takes at least half of it in CPU time (the other
    /// half allows for a loaded machine taking the processor away), a sleep of 0.05 s less than 0.01 s.
    #[cfg(unix)]
    #[test]
    fn counts_computing_not_sleeping() {
        let w = CpuStopwatch::start();
        let t0 = std::time::Instant::now();
        let mut x = 1.0_f64;
        while t0.elapsed().as_secs_f64() < 0.05 {
            x = std::hint::black_box(x * 1.000_000_1);
        }
        let busy = w.elapsed_s().expect("a thread clock on unix");
        assert!(busy > 0.0 && busy <= t0.elapsed().as_secs_f64() + 1e-3, "{busy}");
        let w = CpuStopwatch::start();
        std::thread::sleep(std::time::Duration::from_millis(50));
        let idle = w.elapsed_s().expect("a thread clock on unix");
        assert!((0.0..0.01).contains(&idle), "{idle}");
    }
}
