//! Conductor data of common ACSR and AAAC conductors (to be written).
