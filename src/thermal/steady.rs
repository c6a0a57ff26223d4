//! Steady state (to be written).
