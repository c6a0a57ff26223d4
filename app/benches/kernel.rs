//! Criterion benchmark of the explicit step (`cargo bench --bench kernel`): the three configurations of
//! [`ohl::scheme::configs::Config`] at N = 50, 200, 1000, 5000, reported as node-steps per second (criterion's
//! "elements" throughput). One iteration is a batch of steps from the initial state (a fresh clone,
//! not timed), so that long measurements stay in the same early regime of the weight-release transient.
//! `ohl bench` measures the same kernel with a fixed budget and writes the CSV tables and the plot.

use criterion::{BatchSize, Criterion, Throughput, criterion_group, criterion_main};
use ohl_app::bench::{Config, SIZES};

fn kernel(c: &mut Criterion) {
    for config in Config::ALL {
        let mut group = c.benchmark_group(config.name());
        for n in SIZES {
            // Steps per iteration: about 2e6 node-steps at the largest N, 2000 steps at the smallest.
            let steps = 2000 / (1 + n / 1000);
            group.throughput(Throughput::Elements(((n + 1) * steps) as u64));
            let initial = config.solver(n);
            let dt = initial.params().dt_s;
            group.bench_function(format!("N={n}"), |b| {
                b.iter_batched_ref(
                    || initial.clone(),
                    |s| {
                        for _ in 0..steps {
                            s.step(dt).expect("stable configuration");
                        }
                    },
                    BatchSize::LargeInput,
                )
            });
        }
        group.finish();
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).measurement_time(std::time::Duration::from_secs(2));
    targets = kernel
}
criterion_main!(benches);
