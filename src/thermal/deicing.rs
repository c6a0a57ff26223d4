//! De-icing of a conductor by Joule heating (to be written).
