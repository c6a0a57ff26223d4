//! Ice and wind loads as the design codes state them: radial ice on a conductor ([`radial_ice`]) and the
//! codes' combined ice-and-wind load cases as named presets ([`codes`]). docs/loads.md describes both.

pub mod codes;
pub mod radial_ice;

pub use radial_ice::RadialIce;
