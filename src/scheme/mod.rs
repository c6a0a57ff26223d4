//! Numerical schemes: the explicit staggered-grid leapfrog (3.1), (3.6) with velocity smoothing (3.3)
//! and the Courant time step (3.7).

pub mod conductor_contact;
pub mod configs;
pub mod contact;
pub mod courant;
pub mod electromagnetic;
pub mod explicit;
pub mod line;
pub mod smoothing;

pub use contact::Ground;
pub(crate) use explicit::avx2_available;
pub use explicit::{Diagnostics, Explicit, Instability, InstabilityReason, Loads, StepParams, WindGate, WindLoad};
pub use line::{LineError, LineExplicit, LineInstability};
