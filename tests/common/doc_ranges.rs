//! The ranges of the reference pages (`docs/scenario.md`, `docs/line.md`) and of the validators'
//! messages, read as intervals (shared by `tests/scenario_reference.rs` and `tests/line_reference.rs`).

/// An interval: (lower end open, lower end, upper end, upper end open).
pub type Interval = (bool, f64, f64, bool);

/// The interval at the start of `text` (`[0.01, 20]`, `(0, 1e3]`, `(0, 1)`) and the text after it; `None`
/// if `text` does not start with one whose ends are numbers.
pub fn leading_interval(text: &str) -> Option<(Interval, &str)> {
    let lo_open = match text.chars().next()? {
        '[' => false,
        '(' => true,
        _ => return None,
    };
    let close = text.find([']', ')'])?;
    let (lo, hi) = text[1..close].split_once(',')?;
    let (lo, hi) = (lo.trim().parse().ok()?, hi.trim().parse().ok()?);
    Some(((lo_open, lo, hi, text[close..].starts_with(')')), &text[close + 1..]))
}

/// The interval a validator's message states and the text after it: the first `[a, b]`-like interval,
/// or `must be a finite number >= a, at most b` (`> a` for an open lower end).
pub fn message_interval(allowed: &str) -> Option<(Interval, &str)> {
    for (k, _) in allowed.match_indices(['[', '(']) {
        if let Some(found) = leading_interval(&allowed[k..]) {
            return Some(found);
        }
    }
    let rest = allowed.strip_prefix("must be a finite number ")?;
    let (lo_open, rest) = match rest.strip_prefix(">= ") {
        Some(r) => (false, r),
        None => (true, rest.strip_prefix("> ")?),
    };
    let (lo, rest) = rest.split_once(", at most ")?;
    let end = rest.find([' ', ':']).unwrap_or(rest.len());
    Some(((lo_open, lo.parse().ok()?, rest[..end].parse().ok()?, false), &rest[end..]))
}
