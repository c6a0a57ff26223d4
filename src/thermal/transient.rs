//! Transient (to be written).
