//! Peaks, tracked at every time level (never only at samples), each with its time: the largest segment
//! tension, the largest-magnitude displacement of every probe per component, per support the largest
//! force magnitude and the largest-magnitude component, and for a suspension support the string's
//! largest swing along and across the line; per span of a section its largest segment tension and, with
//! a ground, its least vertical clearance above the ground. Two views are kept:
//!
//! - the run's peaks from `from_s` on ([`Peaks::new`]): by default the time of the first event, so that a
//!   run that settles and then breaks, ices or gusts reports the peaks of what the events do and not the
//!   transient of a start from a shape that is not the equilibrium; 0 for a run without events;
//! - the peaks of every phase: the stretches between events (the first starts at `t = 0`).
//!
//! Besides its extremes, every probe's displacement `d_k(t)` (component `k`, from the chord point) gives
//! over each stretch `[t_a, ...]`:
//!
//! - its **rise** `max_t (d_k(t) - d_k(t_a))` and **fall** `min_t (d_k(t) - d_k(t_a))`, each with its
//!   time: the largest increase and decrease from the stretch's first time level, e.g. the jump of an
//!   ice-shedding span (`k = 3`) above its iced position and the dip of its neighbours;
//! - its **period about the chord point**: each sign change of `d_k` between the levels `t_n` and `t_n+1`
//!   is placed by linear interpolation, `t_c = t_n + (t_n+1 - t_n) d_n / (d_n - d_n+1)` (an `O(dt^2)`
//!   error for a smooth signal); over the `m >= 2` crossings in the direction of the first one (upward or
//!   downward) the period is `(t_c,m - t_c,1) / (m - 1)`, exact for any periodic signal that crosses
//!   twice a period, whatever its mean. A level where `d_k` is exactly zero is not a side: the crossing is taken from the last level with a
//!   sign. An oscillation about another position (a sagging span's vertical motion) never crosses the
//!   chord point and has no period.
//!
//! What is not computed at a level, for the same peaks bit for bit:
//!
//! - a string's swing along the line `a = atan2(y, x)` (in degrees; `y = d . e_l`, `x = -d3`) where it
//!   cannot pass the peak `a_p`: with `x > 0`, `|a| = atan(|y| / x)`, increasing in `|y| / x`; the tangent
//!   of the peak `tan |a_p|` is kept as formed when the peak was set, and a level with `|y| / x < tan |a_p|
//!   (1 - 1e-10)` has `|a|` below `|a_p|` by at least `1e-10 x / (1 + x^2) / atan(x)` relative, which for
//!   `x = tan |a_p| < 1e3` is above `6e-14`: hundreds of roundings more than the few between the
//!   quotient, the tangent, `atan2` and the conversion to degrees. Elsewhere (`x <= 0`, beyond 90 degrees;
//!   a peak within 0.06 degrees of 90; a NaN) the angle is formed and compared as always;
//! - a span's largest tension `max_j |T_j t_j|` ([`crate::scheme::Explicit::max_tension_in`], a pass over
//!   the span's segments) where it cannot raise a peak: under the tension-only law every `T_j >= 0`, the
//!   tangent `t_j = d_j (1 / |d_j|)` is a unit vector to a few roundings and so `|T_j t_j|` as formed
//!   (the products, squares, sum and square root) is `T_j` within about `10 eps` (a segment shorter than
//!   its rest length, the only one whose tangent may be far from unit in the underflow range, has `T_j =
//!   0`); so the span's largest is at most the wire's largest tension (the kernel's,
//!   [`crate::scheme::Explicit::max_tension_n`]) times `1 + 1e-12`. Where that bound lies below the span's
//!   peak in every set the level updates, the span's value could not pass the peak (a peak is replaced
//!   only by a larger value) and it is not formed. A NaN bound, the linear law (whose tensions may be
//!   negative) and tensions from `1e150` N (squares near overflow) always form it;
//! - a level's probe update where every component lies in its **quiet interval** `[lo, hi]`, formed after
//!   each level that changed something: values in it change no peak, rise, fall or crossing, and the
//!   level is only recorded as each crossing's last. The interval is the intersection of `|d| <= |d_p|`
//!   (the peak); `[up(f + o), down(r + o)]` for the rise `r` and fall `f` about the first value `o`,
//!   where `down(x)` is the largest number at most the exact `x` and `up(x)` the least at least it (the
//!   sum and its rounding error by TwoSum), so that `d <= down(r + o)` gives `d - o <= r` exactly and
//!   `d - o` rounds to at most `r`, the rounding being monotone; and the side of the last level with a
//!   sign (`[0, inf)` above, `(-inf, 0]` below; only up to the band where the crossing's side is the
//!   other one or none; only zero before the first level with a sign). Empty where a bound is NaN.
//!   Values outside it take the comparisons of the update as before;
//! - every set's update where no set would change but for recording the level ([`Gate`]): after a level
//!   that updated the sets, where each of them is armed with its quiet intervals and takes no full
//!   updates, one set of bounds is formed from all of them: the least of their largest tensions (the
//!   wire's, each span's), of their supports' largest magnitudes and components' largest magnitudes, the
//!   largest of their least clearances, and the intersection of their probes' quiet intervals. A level
//!   within them passes none of any set's comparisons (each bound is the extreme of the sets' values, and
//!   each test the negation of the update's own comparison, so NaN passes as there) and would only be
//!   recorded as the crossings' last in every set: it is recorded once, and each component's last such
//!   level with a sign is given to the sets' crossings before a set is next updated, ends (an event) or
//!   is read (the end of the run), the state the per-level records would have left (each overwrites the
//!   last with a value with a sign; a level with a sign in every component is the last of all of them
//!   and is kept whole, its buffer swapped with the kept one's). Strings' swings are not bounded and are
//!   updated in every set. The bounds hold for the sets they were formed from: a level updating another
//!   choice of sets (the run's set starting) or any event takes the sets' own updates;
//! - the run's peaks where they are the last phase's: when the run's peaks begin at the level where the
//!   phase's began (`peaks_from_s` at an event, or 0 without events), both sets see the same levels and
//!   perform the same operations on the same values, so the phase's set stands for both until the next
//!   phase begins, when the run's set goes on from a copy of it ([`Peaks::run`]).

use serde::Serialize;

use super::probe::ProbePoint;
use crate::element::scalar::dot3;
use crate::element::tension::LawKind;
use crate::observer::{Control, Level, Observer, OutputError};
use crate::scheme::Ground;

/// The extreme of one displacement component: the value of largest magnitude, with its sign.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Peak {
    /// the displacement of largest magnitude, with its sign [m]
    pub value_m: f64,
    /// when it occurred [s]
    pub time_s: f64,
    /// when it occurred, dimensionless `tau = t U / l` [-]
    pub tau: f64,
}

/// The extreme of a force: the largest value (tension, force magnitude) or the value of largest
/// magnitude with its sign (a force component).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct PeakForce {
    /// the force [N]
    pub value_n: f64,
    /// when it occurred [s]
    pub time_s: f64,
    /// when it occurred, dimensionless `tau = t U / l` [-]
    pub tau: f64,
}

/// The extreme of an angle: the value of largest magnitude, with its sign.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct PeakAngle {
    /// the angle of largest magnitude, with its sign [deg]
    pub value_deg: f64,
    /// when it occurred [s]
    pub time_s: f64,
    /// when it occurred, dimensionless `tau = t U / l` [-]
    pub tau: f64,
}

/// Peaks of the force the wire applies to one support.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct SupportPeaks {
    /// largest magnitude `|F|` [N]
    pub magnitude: PeakForce,
    /// largest-magnitude value of each component `F1, F2, F3` [N]
    pub components: [PeakForce; 3],
    /// a suspension support's string: largest swing from plumb along and across the line [deg]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub swing: Option<[PeakAngle; 2]>,
    /// `tan |swing along|` of the peak above, as formed from it (0 without one) [-]
    #[serde(skip)]
    along_tan: f64,
}

/// The least value of a length (a clearance).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct LeastLength {
    /// the least value [m]
    pub value_m: f64,
    /// when it occurred [s]
    pub time_s: f64,
    /// when it occurred, dimensionless `tau = t U / l` [-]
    pub tau: f64,
}

impl Default for LeastLength {
    fn default() -> Self {
        LeastLength { value_m: f64::INFINITY, time_s: 0.0, tau: 0.0 }
    }
}

/// Peaks of one span of a section.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct SpanPeaks {
    /// largest tension of the span's segments [N]
    pub max_tension: PeakForce,
    /// least vertical clearance of the span's nodes above the ground `min (x3 - h(x2))` [m] (with a ground)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub least_clearance: Option<LeastLength>,
}

/// Sign changes of one displacement component about the chord point (module documentation).
///
/// Plain numbers rather than options, so that the check every level takes is a few comparisons
/// ([`Crossings::at_most_records`]): `last_d = 0` stands for "no level with a sign yet" (a level with
/// `d = 0` is never recorded) and `side` is `+1` above, `-1` below, `0` before `|d|` first left the band.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Crossings {
    /// the last level where the component had a sign: time [s]
    last_t: f64,
    /// ... and value [m] (0: none yet)
    last_d: f64,
    /// the time of the last sign change [s], not yet confirmed by leaving the band
    candidate: f64,
    /// the side the component last left the band on: `+1` above, `-1` below, `0` not yet
    side: f64,
    /// the first crossing: time [s] and whether it was upward (`None` before it)
    first: Option<(f64, bool)>,
    /// crossings in the first one's direction, and the time of the last of them [s]
    same: u64,
    last_same_s: f64,
    /// all crossings
    count: u64,
}

impl Crossings {
    /// The level at `t` [s] with the value `d` [m]; a crossing counts once `|d|` exceeds `band` [m] on
    /// the other side.
    fn update(&mut self, t: f64, d: f64, band: f64) {
        if d == 0.0 || d.is_nan() {
            return;
        }
        let (t0, d0) = (self.last_t, self.last_d);
        if d0 != 0.0 && (d0 < 0.0) != (d < 0.0) {
            self.candidate = t0 + (t - t0) * (d0 / (d0 - d));
        }
        (self.last_t, self.last_d) = (t, d);
        if d.abs() <= band {
            return;
        }
        let up = d > 0.0;
        if self.side != 0.0 && (self.side > 0.0) != up {
            let tc = self.candidate;
            let (_, first_up) = *self.first.get_or_insert((tc, up));
            if up == first_up {
                self.same += 1;
                self.last_same_s = tc;
            }
            self.count += 1;
        }
        self.side = if up { 1.0 } else { -1.0 };
    }

    /// Whether [`Crossings::update`] with the value `d` would at most record the level as the last one
    /// with a sign ([`Crossings::record`]): `d` zero or NaN (no change at all), or no sign change from the
    /// last level with a sign and `d` inside the band or on the side it last left the band on (`side d >
    /// 0`: `side` is `+-1`, so the product is `+-d`, exactly).
    // `!(a > b)`, not `a <= b`: false where the update's own comparison `a > b` is true, NaN included.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    #[inline(always)]
    fn at_most_records(&self, d: f64, band: f64) -> bool {
        let d0 = self.last_d;
        let sign_change = (d0 != 0.0) & ((d0 < 0.0) != (d < 0.0));
        !(d.abs() > 0.0) | (!sign_change & ((d.abs() <= band) | (self.side * d > 0.0)))
    }

    /// What [`Crossings::update`] does where [`Crossings::at_most_records`] holds.
    #[inline(always)]
    fn record(&mut self, t: f64, d: f64) {
        if d.abs() > 0.0 {
            (self.last_t, self.last_d) = (t, d);
        }
    }

    /// The mean period `(t_c,m - t_c,1) / (m - 1)` [s] over the `m >= 2` crossings in the direction of
    /// the first; `None` with fewer.
    pub fn period_s(&self) -> Option<f64> {
        let (first_s, _) = self.first?;
        (self.same >= 2).then(|| (self.last_same_s - first_s) / (self.same - 1) as f64)
    }

    /// The number of crossings, both directions.
    pub fn count(&self) -> u64 {
        self.count
    }
}

/// Everything tracked over one stretch of time.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct PeakSet {
    /// largest segment tension [N]
    pub max_tension: PeakForce,
    /// largest-magnitude displacement of each probe per component (the mid-span probe first) [m]
    pub probes: Vec<[Peak; 3]>,
    /// largest increase of each probe's displacement per component from its value at the stretch's first
    /// time level, `>= 0` (the mid-span probe first) [m]
    pub rises: Vec<[Peak; 3]>,
    /// largest decrease likewise, `<= 0` [m]
    pub falls: Vec<[Peak; 3]>,
    /// each probe's crossings of the chord point per component (the mid-span probe first)
    #[serde(skip)]
    pub crossings: Vec<[Crossings; 3]>,
    /// each probe's displacement at the stretch's first time level [m]
    #[serde(skip)]
    origin: Option<Vec<[f64; 3]>>,
    /// per support (fixed nodes in node order)
    pub supports: Vec<SupportPeaks>,
    /// per span of a section (empty for one span)
    pub spans: Vec<SpanPeaks>,
    /// levels left that take the full update without the comparisons first ([`PeakSet::update`])
    #[serde(skip)]
    full_for: CostHint,
    /// the levels the next failed comparisons give the full update to at once: 0 after comparisons that
    /// passed, then 1, 2, 4, ... up to [`RETRY`] while they keep failing ([`PeakSet::update`])
    #[serde(skip)]
    backoff: CostHint,
    /// each probe component's quiet interval (module documentation)
    #[serde(skip)]
    quiet: QuietIntervals,
}

/// Each probe component's quiet interval `[lo, hi]` (module documentation), formed after a level that
/// changed something (`armed` false until then). Only chooses how to compute: equal to every other, so
/// that sets compare by their peaks alone.
#[derive(Clone, Debug, Default)]
struct QuietIntervals {
    lo: Vec<[f64; 3]>,
    hi: Vec<[f64; 3]>,
    armed: bool,
}

impl PartialEq for QuietIntervals {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

/// The quiet interval of one component (module documentation): peak `p`, rise `r`, fall `f`, crossings
/// `c`, first value `o` [m] and crossing band `band` [m]; only zero before the first level with a sign
/// (a value with a sign would become the crossings' first), empty (`lo > hi`) where a bound is NaN.
fn quiet_interval(p: &Peak, r: &Peak, f: &Peak, c: &Crossings, o: f64, band: f64) -> [f64; 2] {
    const EMPTY: [f64; 2] = [f64::INFINITY, f64::NEG_INFINITY];
    let inf = f64::INFINITY;
    let side = if c.last_d > 0.0 {
        if c.side > 0.0 { [0.0, inf] } else { [0.0, band] }
    } else if c.last_d < 0.0 {
        if c.side < 0.0 { [-inf, 0.0] } else { [-band, 0.0] }
    } else {
        [0.0, 0.0]
    };
    let peak = p.value_m.abs();
    let bounds = [-peak, peak, sum_ceil(f.value_m, o), sum_floor(r.value_m, o), side[0], side[1]];
    if bounds.iter().any(|b| b.is_nan()) {
        return EMPTY;
    }
    [bounds[0].max(bounds[2]).max(bounds[4]), bounds[1].min(bounds[3]).min(bounds[5])]
}

/// The rounded sum `s = a + b` and its error `a + b - s`, exact without overflow (Knuth's TwoSum; NaN
/// with an infinity).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// The largest number at most the exact `a + b`: a value `d` up to it has `d - b <= a` exactly, so
/// `d - b` rounds to at most `a` (rounding is monotone). NaN where the error is NaN (an infinity).
fn sum_floor(a: f64, b: f64) -> f64 {
    let (s, e) = two_sum(a, b);
    if e < 0.0 {
        s.next_down()
    } else if e >= 0.0 {
        s
    } else {
        f64::NAN
    }
}

/// The least number at least the exact `a + b`, likewise.
fn sum_ceil(a: f64, b: f64) -> f64 {
    let (s, e) = two_sum(a, b);
    if e > 0.0 {
        s.next_up()
    } else if e <= 0.0 {
        s
    } else {
        f64::NAN
    }
}

/// A count that only chooses how to compute (not what): equal to every other, so that sets compare by
/// their peaks alone.
#[derive(Clone, Copy, Debug, Default)]
struct CostHint(u32);

impl PartialEq for CostHint {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

/// The most levels that take the full update at once after one that changed a probe's peak, rise, fall
/// or crossing ([`PeakSet::backoff`]).
const RETRY: u32 = 16;

/// One phase: the time between two events.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Phase {
    /// start [s]
    pub start_s: f64,
    /// what started it ("start" or the events applied)
    pub started_by: String,
    /// its peaks
    pub peaks: PeakSet,
}

/// Record the level at `t` [s] with the displacements `d` [m] as each component's crossings' last
/// ([`Crossings::record`]): all a quiet level changes.
#[inline(always)]
fn record_all(c: &mut [[Crossings; 3]], t: f64, d: &[[f64; 3]]) {
    for (c, d) in c.iter_mut().zip(d) {
        for k in 0..3 {
            c[k].record(t, d[k]);
        }
    }
}

/// A support force's magnitude `|F| = sqrt(f1^2 + f2^2 + f3^2)` [N] (the elements' [`dot3`]), formed
/// where it is compared: the gate and each set's update form the same value (a loop forming every
/// support's once per level cost more than the square roots it saves, for the two supports of a span).
#[inline(always)]
fn magnitude(f: &[f64; 3]) -> f64 {
    dot3(*f, *f).sqrt()
}

fn signed(p: &mut Peak, v: f64, t: f64, tau: f64) {
    if v.abs() > p.value_m.abs() {
        *p = Peak { value_m: v, time_s: t, tau };
    }
}

fn signed_force(p: &mut PeakForce, v: f64, t: f64, tau: f64) {
    if v.abs() > p.value_n.abs() {
        *p = PeakForce { value_n: v, time_s: t, tau };
    }
}

fn largest(p: &mut PeakForce, v: f64, t: f64, tau: f64) {
    if v > p.value_n {
        *p = PeakForce { value_n: v, time_s: t, tau };
    }
}

impl PeakSet {
    fn sized(probes: usize, supports: usize, spans: usize) -> Self {
        PeakSet {
            max_tension: PeakForce::default(),
            probes: vec![[Peak::default(); 3]; probes],
            rises: vec![[Peak::default(); 3]; probes],
            falls: vec![[Peak::default(); 3]; probes],
            crossings: vec![[Crossings::default(); 3]; probes],
            origin: None,
            supports: vec![SupportPeaks::default(); supports],
            spans: vec![SpanPeaks::default(); spans],
            full_for: CostHint::default(),
            backoff: CostHint::default(),
            quiet: QuietIntervals { lo: vec![[0.0; 3]; probes], hi: vec![[0.0; 3]; probes], armed: false },
        }
    }

    /// Form every probe component's quiet interval from the peaks as they now are (after the first
    /// level, which sets the first values).
    fn arm(&mut self, band: f64) {
        let Some(o) = self.origin.as_deref() else { return };
        let n = self.probes.len();
        let q = &mut self.quiet;
        for i in 0..n {
            for k in 0..3 {
                let [lo, hi] = quiet_interval(
                    &self.probes[i][k],
                    &self.rises[i][k],
                    &self.falls[i][k],
                    &self.crossings[i][k],
                    o[i][k],
                    band,
                );
                (q.lo[i][k], q.hi[i][k]) = (lo, hi);
            }
        }
        q.armed = true;
    }

    // The negated comparisons are the full update's own (`!(a > b)` is true exactly where it changes
    // nothing, NaN included), so they are written as such.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    fn update(&mut self, cur: &Current) {
        let Current { t, tau, tension, ref disp, ref spans, band_m, .. } = *cur;
        largest(&mut self.max_tension, tension, t, tau);
        for (p, &(tension, clearance)) in self.spans.iter_mut().zip(spans) {
            largest(&mut p.max_tension, tension, t, tau);
            if let Some(c) = clearance {
                let least = p.least_clearance.get_or_insert_with(Default::default);
                if c < least.value_m {
                    *least = LeastLength { value_m: c, time_s: t, tau };
                }
            }
        }
        let origin = self.origin.get_or_insert_with(|| disp.clone());
        let n = self.probes.len();
        let (o, d) = (&origin[..n], &disp[..n]);
        // Every component in its quiet interval: the level is only recorded (which keeps each interval:
        // a recorded value has the sign of the last one).
        if self.full_for.0 == 0 && self.quiet.armed {
            let (lo, hi) = (&self.quiet.lo[..n], &self.quiet.hi[..n]);
            let mut inside = true;
            for i in 0..n {
                for k in 0..3 {
                    inside &= (lo[i][k] <= d[i][k]) & (d[i][k] <= hi[i][k]);
                }
            }
            if inside {
                self.backoff.0 = 0;
                record_all(&mut self.crossings[..n], t, d);
                self.update_supports(cur);
                return;
            }
        }
        // At most levels no probe's peak, rise, fall or crossing changes: the level is then at most
        // recorded as each component's crossings' last one, which is all the full update would do with it.
        // One pass of comparisons finds that out. Where it does not hold at level after level (a
        // displacement growing from level to level, as under heating), the comparisons are left out for
        // the next 1, 2, 4, ... `RETRY` levels, which take the full update at once; where it fails once
        // (a component at rounding level about the chord point, as the mid-span probe's along the line in
        // a symmetric span, changing its sign inside the crossing band), the next level compares again, and
        // the sets return to the quiet intervals and the gate at once. (Indexed slices of one length: a
        // zip of five iterators cost more than the comparisons.)
        if self.full_for.0 == 0 {
            let (p, r, f, c) = (&self.probes[..n], &self.rises[..n], &self.falls[..n], &mut self.crossings[..n]);
            let mut quiet = true;
            for i in 0..n {
                for k in 0..3 {
                    let change = d[i][k] - o[i][k];
                    quiet &= !(d[i][k].abs() > p[i][k].value_m.abs())
                        & !(change > r[i][k].value_m)
                        & !(change < f[i][k].value_m)
                        & c[i][k].at_most_records(d[i][k], band_m);
                }
            }
            if quiet {
                self.backoff.0 = 0;
                record_all(c, t, d);
                self.arm(band_m);
                self.update_supports(cur);
                return;
            }
            self.full_for.0 = self.backoff.0;
            self.backoff.0 = (2 * self.backoff.0).clamp(1, RETRY);
        } else {
            self.full_for.0 -= 1;
        }
        self.quiet.armed = false;
        // Component by component: its peak, rise, fall and crossings, each a function of that component's
        // values alone, so the order across components changes nothing.
        let (p, r, f, c) =
            (&mut self.probes[..n], &mut self.rises[..n], &mut self.falls[..n], &mut self.crossings[..n]);
        for i in 0..n {
            for k in 0..3 {
                let dk = d[i][k];
                signed(&mut p[i][k], dk, t, tau);
                let change = dk - o[i][k];
                if change > r[i][k].value_m {
                    r[i][k] = Peak { value_m: change, time_s: t, tau };
                }
                if change < f[i][k].value_m {
                    f[i][k] = Peak { value_m: change, time_s: t, tau };
                }
                c[i][k].update(t, dk, band_m);
            }
        }
        self.update_supports(cur);
    }

    /// The supports' part of [`PeakSet::update`]: the forces with their magnitudes `|F|`
    /// ([`magnitude`]), then the swings.
    fn update_supports(&mut self, c: &Current) {
        let (t, tau) = (c.t, c.tau);
        for (s, (_, f)) in self.supports.iter_mut().zip(&c.forces) {
            largest(&mut s.magnitude, magnitude(f), t, tau);
            for k in 0..3 {
                signed_force(&mut s.components[k], f[k], t, tau);
            }
        }
        self.update_swings(t, tau, &c.swings);
    }

    /// The strings' swings, the part of [`PeakSet::update_supports`] that [`Gate`] does not bound.
    fn update_swings(&mut self, t: f64, tau: f64, swings: &[Option<([f64; 2], f64)>]) {
        for (s, sw) in self.supports.iter_mut().zip(swings) {
            if let &Some(([y, x], across)) = sw {
                let peaks = s.swing.get_or_insert_with(Default::default);
                // The angle along, `atan2(y, x)` in degrees, only where it could pass the peak (module docs).
                if !(x > 0.0 && s.along_tan < SWING_TAN_BELOW && y.abs() / x < s.along_tan * (1.0 - SWING_MARGIN)) {
                    let along = y.atan2(x).to_degrees();
                    if along.abs() > peaks[0].value_deg.abs() {
                        peaks[0] = PeakAngle { value_deg: along, time_s: t, tau };
                        s.along_tan = along.abs().to_radians().tan();
                    }
                }
                if across.abs() > peaks[1].value_deg.abs() {
                    peaks[1] = PeakAngle { value_deg: across, time_s: t, tau };
                }
            }
        }
    }
}

/// The bounds under which a level changes no set it updates but for the crossings' last levels (module
/// documentation), formed from those sets after a level that updated them: one check for the run's set
/// and the last phase's together, in place of each set's quiet-interval check.
#[derive(Clone, Debug, Default)]
struct Gate {
    /// whether the bounds are those of the sets as they now are (formed after they were last updated)
    valid: bool,
    /// whether the run's set is one of them (besides the last phase's)
    with_run: bool,
    /// the least of the sets' largest tensions [N]
    tension: f64,
    /// per span: the least of the sets' largest tensions [N] and the largest of their least clearances [m]
    spans: Vec<[f64; 2]>,
    /// per probe component (probe by probe, three each): the intersection of the sets' quiet intervals [m]
    lo: Vec<f64>,
    hi: Vec<f64>,
    /// per support: the least of the sets' largest magnitudes and of their components' largest magnitudes
    /// `|F1|, |F2|, |F3|` [N]
    supports: Vec<[f64; 4]>,
    /// per probe component (likewise): the last level with a sign among the levels the gate admitted since
    /// the sets were last given them (`last_d = 0`: none), and whether there are any ([`Gate::give`])
    last_t: Vec<f64>,
    last_d: Vec<f64>,
    pending: bool,
    /// the last admitted level where every component had a sign, if after every record in `last_t`,
    /// `last_d` (`level_pending`): kept whole, its displacements' buffer swapped with the level's
    level_t: f64,
    level_d: Vec<[f64; 3]>,
    level_pending: bool,
}

impl Gate {
    fn sized(probes: usize, supports: usize, spans: usize) -> Self {
        Gate {
            spans: vec![[0.0; 2]; spans],
            lo: vec![0.0; 3 * probes],
            hi: vec![0.0; 3 * probes],
            supports: vec![[0.0; 4]; supports],
            last_t: vec![0.0; 3 * probes],
            last_d: vec![0.0; 3 * probes],
            level_d: vec![[0.0; 3]; probes],
            ..Default::default()
        }
    }

    /// Form the bounds from the sets updated at this level: the last phase's and, `with_run`, the run's.
    /// Valid only where every set would take the quiet-interval path at the next level (armed, no full
    /// updates left) and, with a ground (`clearance`), has a least clearance in every span (else a level's
    /// clearance would be its first). No peak is NaN (a peak is replaced only by a value that compares
    /// above it), so the least and largest of them are the sets' own values.
    fn form(&mut self, phase: &PeakSet, run: Option<&PeakSet>, clearance: bool) {
        self.valid = false;
        self.with_run = run.is_some();
        let sets = [Some(phase), run];
        for s in sets.iter().flatten() {
            if !s.quiet.armed || s.full_for.0 != 0 {
                return;
            }
            if clearance && s.spans.iter().any(|p| p.least_clearance.is_none()) {
                return;
            }
        }
        let inf = f64::INFINITY;
        self.tension = inf;
        self.spans.fill([inf, -inf]);
        self.lo.fill(-inf);
        self.hi.fill(inf);
        self.supports.fill([inf; 4]);
        for s in sets.iter().flatten() {
            self.tension = self.tension.min(s.max_tension.value_n);
            for (b, p) in self.spans.iter_mut().zip(&s.spans) {
                b[0] = b[0].min(p.max_tension.value_n);
                b[1] = b[1].max(p.least_clearance.map_or(-inf, |l| l.value_m));
            }
            for (b, &q) in self.lo.iter_mut().zip(s.quiet.lo.as_flattened()) {
                *b = b.max(q);
            }
            for (b, &q) in self.hi.iter_mut().zip(s.quiet.hi.as_flattened()) {
                *b = b.min(q);
            }
            for (b, p) in self.supports.iter_mut().zip(&s.supports) {
                b[0] = b[0].min(p.magnitude.value_n);
                for k in 0..3 {
                    b[k + 1] = b[k + 1].min(p.components[k].value_n.abs());
                }
            }
        }
        self.valid = true;
    }

    /// Whether the level `c` lies within the bounds: then in every set it would change no peak, rise,
    /// fall, crossing, tension or clearance and only be recorded as the crossings' last level (the
    /// swings aside). Each test is the negation of the update's own comparison against the least
    /// (largest) of the sets' peaks: a value that does not pass it passes none of theirs, NaN included.
    /// Also returns whether every probe component has a sign (is not zero; an admitted value is not NaN).
    // `!(a > b)`, not `a <= b`: true where the update's `a > b` is false, NaN included.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    #[inline(always)]
    fn admits(&self, c: &Current) -> (bool, bool) {
        let mut ok = !(c.tension > self.tension);
        for (&(tension, clearance), b) in c.spans.iter().zip(&self.spans) {
            ok &= !(tension > b[0]);
            if let Some(x) = clearance {
                ok &= !(x < b[1]);
            }
        }
        for ((_, f), b) in c.forces.iter().zip(&self.supports) {
            ok &= !(magnitude(f) > b[0]) & !(f[0].abs() > b[1]) & !(f[1].abs() > b[2]) & !(f[2].abs() > b[3]);
        }
        let n = self.lo.len();
        let (lo, hi, d) = (&self.lo[..n], &self.hi[..n], &c.disp.as_flattened()[..n]);
        let mut signed = true;
        for j in 0..n {
            ok &= (lo[j] <= d[j]) & (d[j] <= hi[j]);
            signed &= d[j] != 0.0;
        }
        (ok, signed)
    }

    /// Keep the admitted level at `t` [s] with the displacements `d` [m] as each component's last with a
    /// sign, what [`Crossings::record`] would do in every set. Where every component has a sign
    /// (`signed`, nearly every level), the level is the last of every component: it is kept whole by
    /// swapping `d`'s buffer with `level_d` (the caller writes every entry of `d` again before it is
    /// next read), and moved into the per-component records only before a level with a zero component
    /// is recorded or the records are given ([`Gate::settle_level`]).
    #[inline(always)]
    fn record(&mut self, t: f64, d: &mut Vec<[f64; 3]>, signed: bool) {
        self.pending = true;
        if signed {
            std::mem::swap(&mut self.level_d, d);
            self.level_t = t;
            self.level_pending = true;
            return;
        }
        self.settle_level();
        let n = self.last_d.len();
        let (lt, ld, d) = (&mut self.last_t[..n], &mut self.last_d[..n], &d.as_flattened()[..n]);
        for j in 0..n {
            if d[j].abs() > 0.0 {
                (lt[j], ld[j]) = (t, d[j]);
            }
        }
    }

    /// Move the level kept whole into the per-component records: it is the last of every component.
    fn settle_level(&mut self) {
        if self.level_pending {
            for ((lt, ld), &x) in self.last_t.iter_mut().zip(&mut self.last_d).zip(self.level_d.as_flattened()) {
                (*lt, *ld) = (self.level_t, x);
            }
            self.level_pending = false;
        }
    }

    /// Give the sets the gate admitted levels for (the last phase's and, if it was one of them, the run's)
    /// each component's last admitted level with a sign as their crossings' last: the state the records
    /// at every admitted level would have left (each overwrites the last with a value with a sign), before
    /// a set is updated, ends or is read.
    fn give(&mut self, phase: &mut PeakSet, run: &mut PeakSet) {
        if !self.pending {
            return;
        }
        self.settle_level();
        for set in [Some(phase), self.with_run.then_some(run)].into_iter().flatten() {
            for (c, (&lt, &ld)) in set.crossings.as_flattened_mut().iter_mut().zip(self.last_t.iter().zip(&self.last_d))
            {
                if ld != 0.0 {
                    (c.last_t, c.last_d) = (lt, ld);
                }
            }
        }
        self.last_d.fill(0.0);
        self.pending = false;
    }
}

/// The peak tracker.
pub struct Peaks {
    from_s: f64,
    probes: Vec<ProbePoint>,
    supports: usize,
    spans: Vec<(usize, usize)>,
    ground: Option<Ground>,
    /// the run's peaks from `from_s` on, unless `run_is_phase` ([`Peaks::run`])
    run: PeakSet,
    /// every phase's peaks
    pub phases: Vec<Phase>,
    current: Current,
    /// whether the last phase's peaks have been updated since the phase began
    phase_updated: bool,
    /// whether the run's peaks have begun (a level at or after `from_s` was observed)
    run_started: bool,
    /// whether the run's peaks are those of the last phase: both began empty at the same level and have
    /// seen the same levels since, so their updates are the same operations on the same values and one
    /// set is updated for both (`run` is stale then; it is the phase's until the next phase begins)
    run_is_phase: bool,
    /// the bounds under which a level changes no set but for the crossings' last levels ([`Gate`])
    gate: Gate,
    /// levels the gate admitted (for the tests)
    #[cfg(test)]
    admitted: usize,
}

/// The tracked values at one time level.
#[derive(Clone, Default)]
struct Current {
    t: f64,
    tau: f64,
    /// largest segment tension [N]
    tension: f64,
    /// probe displacements [m] (every entry written at every level: after a level the gate admitted, the
    /// buffer holds an earlier level's, swapped into [`Gate::record`])
    disp: Vec<[f64; 3]>,
    /// support forces [N]
    forces: Vec<(usize, [f64; 3])>,
    /// string swings per support (`None` without a string; the list is empty where the wire has no
    /// strings): the arguments `[y, x]` of the angle along, `atan2(y, x)` [m], and the angle across [deg]
    swings: Vec<Option<([f64; 2], f64)>>,
    /// per span: largest tension [N] and least clearance [m]
    spans: Vec<(f64, Option<f64>)>,
    /// the band a crossing must leave [m]: `1e-9` of the wire's chord at the first level
    band_m: f64,
}

/// The relative margin below the peak's tangent under which a string's swing along the line cannot be a
/// new peak (module docs): far above the roundings between `|y| / x`, the tangent as formed from the peak
/// in degrees and the angles `atan2` returns (a few units of `eps = 2.2e-16` each).
const SWING_MARGIN: f64 = 1e-10;

/// The peak's tangent from which the swing's angle along is always formed (module docs): near 90 degrees
/// the angle changes too little with the tangent for the margin (`d atan(x) = dx / (1 + x^2)`).
const SWING_TAN_BELOW: f64 = 1e3;

/// A crossing counts once the displacement passes this fraction of the wire's chord (module docs).
const CROSSING_BAND: f64 = 1e-9;

/// The relative margin of a span's largest tension over the wire's (module docs): far above the few
/// roundings (about `10 eps = 2.2e-15`) between a segment's tension `T` and `|T t|` as formed.
const SPAN_BOUND: f64 = 1e-12;

/// The wire's largest tension below which the span bound is used [N]: the squares of the forces stay
/// far from overflow (`(1e150)^2 = 1e300`), so a span's largest is never an infinity from them.
const SPAN_BOUND_BELOW_N: f64 = 1e150;

impl Peaks {
    /// Track `probes` (the mid-span probe first), `supports` supports and the `spans` of a section (first
    /// and last node of each; empty for one span) with their clearance above `ground`; the run's peaks
    /// count from `from_s` [s].
    pub fn new(
        from_s: f64,
        probes: Vec<ProbePoint>,
        supports: usize,
        spans: Vec<(usize, usize)>,
        ground: Option<Ground>,
    ) -> Self {
        let n = probes.len();
        let k = spans.len();
        Peaks {
            from_s,
            run: PeakSet::sized(n, supports, k),
            phases: vec![Phase { start_s: 0.0, started_by: "start".into(), peaks: PeakSet::sized(n, supports, k) }],
            probes,
            supports,
            spans,
            ground,
            current: Current { disp: vec![[0.0; 3]; n], spans: vec![(0.0, None); k], ..Default::default() },
            phase_updated: false,
            run_started: false,
            run_is_phase: false,
            gate: Gate::sized(n, supports, k),
            #[cfg(test)]
            admitted: 0,
        }
    }

    /// The run's peaks from `from_s` on.
    pub fn run(&self) -> &PeakSet {
        if self.run_is_phase {
            &self.phases.last().expect("the first phase exists from the start").peaks
        } else {
            &self.run
        }
    }

    /// The time from which the run's peaks count [s].
    pub fn from_s(&self) -> f64 {
        self.from_s
    }

    /// Give the sets the crossings' last levels the gate kept ([`Gate::give`]).
    fn give_records(&mut self) {
        let phase = &mut self.phases.last_mut().expect("the first phase exists from the start").peaks;
        self.gate.give(phase, &mut self.run);
    }
}

impl Observer for Peaks {
    fn observe(&mut self, level: &Level) -> Result<Control, OutputError> {
        let s = level.solver;
        let c = &mut self.current;
        (c.t, c.tau) = (level.t_s, level.tau());
        if c.band_m == 0.0 {
            let w = s.wire();
            let (a, b) = (w.position(0), w.position(w.segments()));
            let chord = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2) + (b[2] - a[2]).powi(2)).sqrt();
            c.band_m = CROSSING_BAND * chord;
        }
        let x = ProbePoint::coordinates(s.wire());
        for (d, p) in c.disp.iter_mut().zip(&self.probes) {
            *d = p.displacement_in(x);
        }
        s.support_forces(&mut c.forces);
        let w = s.wire();
        c.swings.clear();
        // Without strings no support has a swing (an empty list pairs with no support in the update).
        for &(node, _) in if w.insulators.is_empty() { &[][..] } else { &c.forces[..] } {
            let string = w.insulators.iter().find(|i| i.node == node);
            c.swings.push(string.map(|i| {
                let (along, across) = i.swing_parts(w.position(node), i.along);
                (along, across.to_degrees())
            }));
        }
        c.tension = s.max_tension_n();
        let phase = self.phases.last_mut().expect("the first phase exists from the start");
        let run_level = c.t >= self.from_s - super::clock::LANDING * s.params().dt_s;
        // A span's largest `|T t|` is at most the wire's largest tension `T_max` (the kernel's, every
        // segment) times `1 + SPAN_BOUND` (module docs): below every peak it could raise, it is not formed.
        let bounded = w.law == LawKind::TensionOnly && c.tension < SPAN_BOUND_BELOW_N;
        let bound = c.tension * (1.0 + SPAN_BOUND);
        let with_run_peaks = run_level && !self.run_is_phase;
        // (`c.spans` has one entry per span from the start: written in place.)
        for (((&(first, last), out), p), r) in
            self.spans.iter().zip(&mut c.spans).zip(&phase.peaks.spans).zip(&self.run.spans)
        {
            let clearance = self.ground.as_ref().map(|g| g.least_clearance_m(&w.x, first..=last));
            let mut least_peak = p.max_tension.value_n;
            if with_run_peaks {
                least_peak = least_peak.min(r.max_tension.value_n);
            }
            let tension = if bounded && bound < least_peak { f64::NEG_INFINITY } else { s.max_tension_in(first..last) };
            *out = (tension, clearance);
        }
        let mut with_run = false;
        if !self.run_is_phase && run_level {
            if !self.run_started && !self.phase_updated {
                // The run's peaks begin at this level, as the phase's did: from here on they are the
                // phase's (until the next phase begins, `event`).
                self.run_is_phase = true;
            } else {
                with_run = true;
            }
            self.run_started = true;
        }
        let gate = &mut self.gate;
        let (admitted, signed) = if gate.valid && gate.with_run == with_run { gate.admits(c) } else { (false, false) };
        if admitted {
            // Every set updated at this level would only record it (module docs): once for all of them.
            gate.record(c.t, &mut c.disp, signed);
            if !c.swings.is_empty() {
                if with_run {
                    self.run.update_swings(c.t, c.tau, &c.swings);
                }
                phase.peaks.update_swings(c.t, c.tau, &c.swings);
            }
            #[cfg(test)]
            {
                self.admitted += 1;
            }
        } else {
            gate.give(&mut phase.peaks, &mut self.run);
            if with_run {
                self.run.update(c);
            }
            phase.peaks.update(c);
            gate.form(&phase.peaks, with_run.then_some(&self.run), self.ground.is_some());
        }
        self.phase_updated = true;
        Ok(Control::Continue)
    }

    fn finish(&mut self, _level: &Level, _ending: &crate::observer::Ending) -> Result<(), OutputError> {
        self.give_records();
        Ok(())
    }

    fn event(&mut self, t_s: f64, what: &str) {
        // The sets the gate was formed for end or change here.
        self.give_records();
        self.gate.valid = false;
        let last = self.phases.last_mut().expect("the first phase exists from the start");
        if self.run_is_phase {
            // The phase ends or starts afresh: the run's peaks go on from its values.
            self.run.clone_from(&last.peaks);
            self.run_is_phase = false;
        }
        if last.start_s == t_s && last.started_by != "start" {
            last.started_by = format!("{}; {what}", last.started_by);
            return;
        }
        let peaks = PeakSet::sized(self.probes.len(), self.supports, self.spans.len());
        if last.start_s == t_s {
            // events at t = 0: they start the first phase
            *last = Phase { start_s: t_s, started_by: what.to_string(), peaks };
        } else {
            self.phases.push(Phase { start_s: t_s, started_by: what.to_string(), peaks });
        }
        self.phase_updated = false;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Levels `t_n = n dt` of `d(t)`, fed to one component's crossings.
    fn crossings_of(d: impl Fn(f64) -> f64, dt: f64, end_s: f64) -> Crossings {
        let mut c = Crossings::default();
        let steps = (end_s / dt).round() as usize;
        for n in 0..=steps {
            let t = n as f64 * dt;
            c.update(t, d(t), 1e-9);
        }
        c
    }

    /// `d = 0.5 + sin(2 pi t)`: the crossings are unevenly spaced (downward at `7/12`, upward at `11/12` of
    /// each period), so only crossings of one direction give the period, 1 s. Linear interpolation places
    /// a crossing within `dt^2 max|d''| / (8 |d'|) = dt^2 (2 pi)^2 0.5 / (8 2 pi 0.866) = 0.453 dt^2` of the
    /// true one, so the period over `m - 1` periods is within `2 (0.453 dt^2) / (m - 1)`.
    #[test]
    fn period_from_one_direction_of_crossings_of_an_offset_sine() {
        let w = 2.0 * std::f64::consts::PI;
        for dt in [1e-2, 1e-3] {
            let c = crossings_of(|t| 0.5 + (w * t).sin(), dt, 5.3);
            // crossings at 7/12, 11/12, 19/12, ... up to 5.3 s: 5 downward, 5 upward (the last at 59/12)
            assert_eq!(c.count(), 10);
            let bound = 2.0 * 0.453 * dt * dt / 4.0;
            let p = c.period_s().unwrap();
            assert!((p - 1.0).abs() <= bound, "dt = {dt}: period {p}, bound {bound}");
        }
    }

    /// A level exactly at zero is not a side; touching zero is no crossing; one crossing gives no period.
    #[test]
    fn zero_levels_and_too_few_crossings() {
        let mut c = Crossings::default();
        for (t, d) in [(0.0, 1.0), (1.0, 0.0), (2.0, 1.0)] {
            c.update(t, d, 1e-9);
        }
        assert_eq!((c.count(), c.period_s()), (0, None));
        for (t, d) in [(3.0, 0.0), (4.0, -1.0)] {
            c.update(t, d, 1e-9);
        }
        // from (2, 1) to (4, -1): one crossing at 3 s
        assert_eq!((c.count(), c.period_s()), (1, None));
        assert_eq!(c.first, Some((3.0, false)));
        let still = crossings_of(|_| -2.0, 0.1, 10.0);
        assert_eq!((still.count(), still.period_s()), (0, None));
    }

    /// Rounding noise about zero (here +-3e-12 m, alternating every level) stays inside the band and is no
    /// oscillation; noise on a real crossing leaves its time at the last sign change.
    #[test]
    fn noise_inside_the_band_is_no_crossing() {
        let noise = crossings_of(|t| if ((t * 10.0).round() as i64) % 2 == 0 { 3e-12 } else { -3e-12 }, 0.1, 10.0);
        assert_eq!((noise.count(), noise.period_s()), (0, None));
        let mut c = Crossings::default();
        for (t, d) in [(0.0, 1.0), (1.0, 1e-12), (2.0, -1e-12), (3.0, 1e-12), (4.0, -1e-12), (5.0, -1.0)] {
            c.update(t, d, 1e-9);
        }
        assert_eq!(c.count(), 1);
        assert_eq!(c.first, Some((3.5, false)));
    }

    /// The run's peaks ([`Peaks::run`]) are those of a set updated at every level from `from_s` on with
    /// every value formed, whether they are kept apart or shared with the last phase (from an event at
    /// `from_s`, from the first level, from a later event, across several events), the crossings' and
    /// origins' state too; the phases' peaks likewise, though the spans' largest tensions are left out
    /// where the wire's bounds them below the peaks; and with the levels the gate admits only recorded
    /// once for both sets ([`Gate`]), the crossings' last levels given to them afterwards.
    #[test]
    fn run_peaks_shared_with_a_phase_are_the_separately_updated_ones() {
        use crate::scheme::configs::Config;
        let (mut skipped, mut admitted) = (0, 0);
        // (from_s, event levels)
        for (from_s, events) in [
            (0.0, vec![]),
            (0.0, vec![0, 90]),
            (0.0, vec![0, 200]),
            (60.0, vec![60, 130]),
            (45.0, vec![60]),
            (60.0, vec![30, 60, 61]),
        ] {
            let mut s = Config::Wind3d.solver(40);
            let dt = s.params().dt_s;
            let from_s = from_s * dt;
            let probes = vec![ProbePoint::new("mid", 0.5, s.wire()), ProbePoint::new("q", 0.25, s.wire())];
            let supports = s.wire().supports().len();
            let mut peaks = Peaks::new(from_s, probes, supports, vec![(0, 20), (20, 40)], None);
            let mut reference = PeakSet::sized(2, supports, 2);
            let mut phase = PeakSet::sized(2, supports, 2);
            for n in 0..2000 {
                let t = s.time_s();
                if events.contains(&n) {
                    peaks.event(t, "event");
                    phase = PeakSet::sized(2, supports, 2);
                    // less wind at each event: the tension falls below the phase's peak
                    s.loads_mut().wind_scale = 1.0 - 0.004 * n as f64;
                }
                s.evaluate_forces();
                peaks.observe(&Level { solver: &s, t_s: t, tau_per_s: 1.0 }).unwrap();
                // Every value formed, the spans' largest tensions too.
                let mut all = peaks.current.clone();
                // (The gate may have swapped the level's displacements into its record: formed again.)
                all.disp = peaks.probes.iter().map(|p| p.displacement(s.wire())).collect();
                skipped += all.spans.iter().filter(|p| p.0 == f64::NEG_INFINITY).count();
                all.spans = vec![(s.max_tension_in(0..20), None), (s.max_tension_in(20..40), None)];
                if t >= from_s - crate::output::clock::LANDING * dt {
                    reference.update(&all);
                }
                phase.update(&all);
                // The crossings' last levels the gate keeps, given to copies of the sets (the sets get them
                // only before they are updated, end or are read, so they accumulate over admitted levels).
                let (mut last, mut run) = (peaks.phases.last().unwrap().peaks.clone(), peaks.run.clone());
                peaks.gate.clone().give(&mut last, &mut run);
                let run = if peaks.run_is_phase { &last } else { &run };
                assert_eq!(run, &reference, "from {from_s}, events {events:?}, level {n}");
                assert_eq!(&last, &phase, "from {from_s}, events {events:?}, level {n}");
                s.step(dt).unwrap();
            }
            assert_eq!(peaks.phases.len(), 1 + events.iter().filter(|&&n| n > 0).count());
            admitted += peaks.admitted;
        }
        assert!(skipped > 0, "no span's largest tension was left out");
        assert!(admitted > 50, "the gate admitted {admitted} levels");
    }

    /// The gate's records ([`Gate::record`], [`Gate::give`]) leave every crossing's last level as the
    /// per-level records do: levels without zeros (kept whole, buffers swapped), a component zero
    /// throughout half of them and every one now and then (the level kept whole moved into the
    /// per-component records first), given at irregular intervals to two sets.
    #[test]
    fn gate_records_are_the_per_level_records() {
        let mut next = crate::test_rng::uniform(11);
        let mut gate = Gate::sized(2, 0, 0);
        gate.with_run = true;
        let (mut phase, mut run) = (PeakSet::sized(2, 0, 0), PeakSet::sized(2, 0, 0));
        let (mut phase_ref, mut run_ref) = (phase.clone(), run.clone());
        let mut disp = vec![[0.0; 3]; 2];
        let (mut zeros, mut whole) = (0, 0);
        for n in 0..5000 {
            let t = n as f64 * 0.01;
            for (j, d) in disp.iter_mut().flatten().enumerate() {
                // component 4 zero throughout the first half, each now and then
                *d = if (j == 4 && n < 2500) || next() < 0.01 { 0.0 } else { next() - 0.5 };
            }
            let signed = disp.as_flattened().iter().all(|&x| x != 0.0);
            (zeros, whole) = (zeros + usize::from(!signed), whole + usize::from(signed));
            for set in [&mut phase_ref, &mut run_ref] {
                record_all(&mut set.crossings, t, &disp);
            }
            gate.record(t, &mut disp, signed);
            if next() < 0.1 {
                gate.give(&mut phase, &mut run);
                assert_eq!((&phase.crossings, &run.crossings), (&phase_ref.crossings, &run_ref.crossings), "level {n}");
            }
        }
        assert!(zeros > 2500 && whole > 1000, "{zeros} levels with a zero, {whole} without");
    }

    /// A string's swing peaks with the angle along formed only where it could pass the peak are those
    /// formed every level: swings growing by steps of a few roundings near the peak, across 90 degrees
    /// (`x <= 0`), near 90 degrees, at zero and NaN.
    #[test]
    fn swing_peaks_skipping_the_angle_are_the_formed_ones() {
        let mut set = PeakSet::sized(0, 1, 0);
        let mut want = [PeakAngle::default(); 2];
        const H: f64 = std::f64::consts::FRAC_PI_2;
        let mut levels: Vec<(f64, f64)> = Vec::new();
        for (i, a) in
            [0.0_f64, 0.3, 0.5, 0.5, 0.7, 1.2, H - 1e-4, H - 1e-5, H + 1e-5, 2.0, 3.1, 3.0, -3.1].iter().enumerate()
        {
            for step in -40..=40 {
                // angles a few roundings apart around `a`, and the same mirrored in y
                let b = a * (1.0 + step as f64 * 1e-16);
                levels.push(((i as f64 + 1.0) * b.sin(), b.cos()));
                levels.push((-(i as f64 + 1.0) * b.sin() * 0.999, b.cos()));
            }
        }
        levels.extend([(0.0, 0.0), (f64::NAN, 1.0), (1.0, f64::NAN), (0.0, -1.0)]);
        for (n, &(y, x)) in levels.iter().enumerate() {
            let t = n as f64;
            let across = (n % 7) as f64 - 3.0;
            let c =
                Current { t, forces: vec![(0, [0.0; 3])], swings: vec![Some(([y, x], across))], ..Default::default() };
            set.update(&c);
            let along = y.atan2(x).to_degrees();
            for (k, a) in [along, across].into_iter().enumerate() {
                if a.abs() > want[k].value_deg.abs() {
                    want[k] = PeakAngle { value_deg: a, time_s: t, tau: 0.0 };
                }
            }
            assert_eq!(set.supports[0].swing, Some(want), "level {n}: y {y:e}, x {x:e}");
        }
    }

    /// The rise and fall count from the stretch's first level, whatever the displacement was before it.
    #[test]
    fn rise_and_fall_are_the_changes_from_the_first_level() {
        let mut set = PeakSet::sized(1, 0, 0);
        // an iced mid-span 14.8 m below the chord jumps by 18.9 m, then falls back past its start
        for (t, z) in [(1.0, -14.8), (2.0, -5.0), (3.0, 4.1), (4.0, -10.0), (5.0, -15.5)] {
            let c = Current { t, tau: t / 100.0, disp: vec![[0.0, 0.0, z]], ..Default::default() };
            set.update(&c);
        }
        let (r, f) = (set.rises[0][2], set.falls[0][2]);
        assert!((r.value_m - 18.9).abs() < 1e-12 && r.time_s == 3.0, "{r:?}");
        assert!((f.value_m + 0.7).abs() < 1e-12 && f.time_s == 5.0, "{f:?}");
        assert_eq!((set.rises[0][0], set.falls[0][1]), (Peak::default(), Peak::default()));
        assert_eq!(set.probes[0][2].value_m, -15.5);
    }

    /// The quiet interval's edges for the rise and fall: `d = sum_floor(a, b)` has `d - b` rounding to at
    /// most `a`, `sum_ceil` to at least it, over sums of numbers of many magnitudes and signs (where the
    /// rounded sum is above or below the exact one), with zeros and infinities.
    #[test]
    fn rounded_edges_keep_the_difference_on_their_side() {
        let mut next = crate::test_rng::uniform(7);
        let (mut above, mut below) = (0, 0);
        for _ in 0..200_000 {
            let a = (next() - 0.5) * 10f64.powi((next() * 12.0) as i32 - 6);
            let b = (next() - 0.5) * 10f64.powi((next() * 12.0) as i32 - 6);
            let (lo, hi) = (sum_ceil(a, b), sum_floor(a, b));
            assert!(hi - b <= a && lo - b >= a, "{a:e} {b:e}: [{lo:e}, {hi:e}]");
            assert!(lo <= hi.next_up() && hi <= lo);
            above += usize::from(a + b > hi);
            below += usize::from(a + b < lo);
        }
        assert!(above > 1000 && below > 1000, "{above} rounded sums above the exact one, {below} below");
        assert_eq!((sum_floor(0.0, 0.0), sum_ceil(-0.0, 0.0)), (0.0, 0.0));
        assert!(sum_floor(f64::INFINITY, 1.0).is_nan() && sum_ceil(1.0, f64::NEG_INFINITY).is_nan());
    }

    /// The comparisons' back-off: a component at rounding level about the chord point that changes its
    /// sign inside the crossing band at one level (the mid-span probe's along-line displacement of a
    /// symmetric span) costs that level's full update and one more level of comparisons, after which the
    /// set is on its quiet intervals again; a component that changes at every level (a steady growth)
    /// leaves the comparisons out for 1, 2, 4, ... 16 levels. Either way the peaks are those of a set
    /// that takes the full update at every level.
    #[test]
    fn comparisons_back_off_only_while_they_keep_failing() {
        let band = 1e-9 * 400.0;
        let (mut set, mut reference) = (PeakSet::sized(1, 0, 0), PeakSet::sized(1, 0, 0));
        let level = |set: &mut PeakSet, reference: &mut PeakSet, n: usize, d: [f64; 3]| {
            let t = n as f64 * 0.01;
            let c = Current { t, tau: t, disp: vec![d], band_m: band, ..Default::default() };
            set.update(&c);
            reference.full_for.0 = u32::MAX;
            reference.update(&c);
            assert_eq!(set, reference, "level {n}");
            set.quiet.armed && set.full_for.0 == 0
        };
        // Quiet: a fixed blow-out and sag, the along-line component at +-3e-13 m (inside the band).
        let mut n = 0;
        for _ in 0..10 {
            level(&mut set, &mut reference, n, [5.0, 3e-13, -12.0]);
            n += 1;
        }
        for cycle in 0..6 {
            // A sign change inside the band: this level takes the full update, the next compares and arms.
            let d = [5.0, if cycle % 2 == 0 { -3e-13 } else { 3e-13 }, -12.0];
            assert!(!level(&mut set, &mut reference, n, d), "level {n}");
            assert!(level(&mut set, &mut reference, n + 1, d), "level {}", n + 1);
            assert!(level(&mut set, &mut reference, n + 2, d), "level {}", n + 2);
            n += 3;
        }
        // Growth at every level: the full update at every level, the comparisons at levels 1, 2, 4, 8, 16
        // and then every 17th level apart from the first failing one.
        let mut compared = Vec::new();
        for m in 0..80 {
            let before = set.full_for.0;
            level(&mut set, &mut reference, n, [5.0 + 1e-3 * (m + 1) as f64, 3e-13, -12.0]);
            if before == 0 {
                compared.push(m);
            }
            n += 1;
        }
        assert_eq!(&compared[..7], &[0, 1, 3, 6, 11, 20, 37], "levels with comparisons: {compared:?}");
    }

    /// A set updated as the runs do it (quiet intervals, the comparisons, the full update after a change)
    /// equals one that takes the full update at every level, field for field including every crossing's
    /// state: two probes whose components oscillate about offsets, grow and decay, stay inside the
    /// crossing band, are exactly zero, sit exactly on a peak and on `o + r` or `o + f` as rounded, and a
    /// NaN level. Most levels must be decided by the quiet intervals (else the test would not test them).
    #[test]
    fn quiet_intervals_change_nothing() {
        let band = 1e-9 * 400.0;
        let mut set = PeakSet::sized(2, 0, 0);
        let mut reference = PeakSet::sized(2, 0, 0);
        let (mut inside, mut levels) = (0, 0);
        let signal = |n: usize, i: usize, k: usize| -> f64 {
            let t = n as f64 * 0.01;
            let (a, w, off) = (0.5 + i as f64, 2.0 + k as f64, [0.0, 0.3, -0.7][k] * (1.0 - 0.5 * i as f64));
            let envelope = if n < 2000 { 1.0 } else { (-(t - 20.0) / 5.0).exp() };
            match n % 997 {
                500 if k == 0 => 0.0,
                501 if k == 1 => 0.5 * band,
                _ => off * (1.0 + 1e-3 * t) + a * envelope * (w * t).sin(),
            }
        };
        for n in 0..6000 {
            let t = n as f64 * 0.01;
            let mut disp = vec![[0.0; 3]; 2];
            for (i, d) in disp.iter_mut().enumerate() {
                for (k, x) in d.iter_mut().enumerate() {
                    *x = signal(n, i, k);
                }
            }
            if n % 1499 == 700 {
                // exactly on the peak and on the rise's and fall's edges as rounded
                disp[0][0] = reference.probes[0][0].value_m;
                if let Some(o) = &reference.origin {
                    disp[1][2] = reference.rises[1][2].value_m + o[1][2];
                    disp[0][1] = reference.falls[0][1].value_m + o[0][1];
                }
            }
            if let (1100 | 1200 | 1300 | 1400, Some(o)) = (n % 1499, &reference.origin) {
                // just beyond a rise's edge (probe 0, x3: values in about [-1.2, -0.2]) and a fall's
                // (probe 1, x2: about [-1.35, 1.65]), where neither the peak nor the side binds: by 1e-9 m,
                // and by the least change that rounds beyond them (new rises and falls)
                let (r, f) = (reference.rises[0][2].value_m, reference.falls[1][1].value_m);
                match n % 1499 {
                    1100 => disp[0][2] = r + o[0][2] + 1e-9,
                    1200 => disp[1][1] = f + o[1][1] - 1e-9,
                    1300 => disp[0][2] = o[0][2] + r.next_up(),
                    _ => disp[1][1] = o[1][1] + f.next_down(),
                }
            }
            if n < 40 {
                // exactly zero for the first levels, then inside the band on either side
                disp[1][0] = if n < 20 { 0.0 } else { 0.3 * band * if n % 2 == 0 { 1.0 } else { -1.0 } };
            }
            if n == 4321 {
                disp[1][0] = f64::NAN;
            }
            let c = Current { t, tau: t / 10.0, disp, band_m: band, ..Default::default() };
            let armed = set.quiet.armed && set.full_for.0 == 0;
            let (lo, hi) = (set.quiet.lo.clone(), set.quiet.hi.clone());
            set.update(&c);
            reference.full_for.0 = u32::MAX;
            reference.update(&c);
            assert_eq!(set, reference, "level {n}");
            for (i, d) in c.disp.iter().enumerate() {
                for k in 0..3 {
                    assert_eq!(set.crossings[i][k], reference.crossings[i][k], "level {n} probe {i} component {k}");
                }
                inside += usize::from(armed && (0..3).all(|k| lo[i][k] <= d[k] && d[k] <= hi[i][k]));
            }
            levels += 2;
        }
        assert!(inside > levels / 2, "{inside} of {levels} probe levels inside their quiet intervals");
        assert!(set.crossings[0][0].count() > 10 && set.rises[1][2].value_m > 0.0);
    }
}
