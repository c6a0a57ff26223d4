//! The values of one `--vary FIELD=VALUES`: a list `10,15,20` or a range `START:STOP:STEP`.
//!
//! A range is inclusive at both ends: `10:30:5` is 10, 15, 20, 25, 30. STOP is included when it is a
//! whole number of steps from START, to within 1e-9 of a step (so float rounding in `(STOP - START) /
//! STEP` never loses or adds the last value); otherwise the range ends at the last value before STOP.
//! Each value is `START + k STEP` (a product, not a running sum, so errors do not accumulate), written
//! with as many decimals as the most precise of the three numbers and without trailing zeros: `0.1:0.3:0.1`
//! gives `0.1`, `0.2`, `0.3`, the same numbers as if they had been typed. STEP may be negative for a
//! descending range. Values are kept as text; each case converts them to the type of its field
//! ([`super::overrides`]).

/// Most values in one range.
pub const MAX_RANGE_VALUES: usize = 1_000_000;

/// Why a list of values cannot be read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("--vary {field}={text}: {reason}")]
pub struct ValuesError {
    /// the field
    pub field: String,
    /// the values as written
    pub text: String,
    /// what is wrong and what is expected
    pub reason: String,
}

/// The values of `text` (after `FIELD=`): a range if it contains `:` and no `,`, else a comma-separated
/// list (items trimmed, none empty).
pub fn parse_values(field: &str, text: &str) -> Result<Vec<String>, ValuesError> {
    let fail = |reason: String| ValuesError { field: field.into(), text: text.into(), reason };
    if text.contains(':') && !text.contains(',') {
        return parse_range(text).map_err(fail);
    }
    let items: Vec<String> = text.split(',').map(|s| s.trim().to_string()).collect();
    if let Some(k) = items.iter().position(|s| s.is_empty()) {
        return Err(fail(format!(
            "value {} of the list is empty; expected a list VALUE,VALUE,... or a range START:STOP:STEP",
            k + 1
        )));
    }
    Ok(items)
}

/// The values of the range `START:STOP:STEP` ([module docs](self)), or why it is not one.
pub fn parse_range(text: &str) -> Result<Vec<String>, String> {
    let parts: Vec<&str> = text.split(':').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(format!("a range is START:STOP:STEP (three numbers), found {} part(s)", parts.len()));
    }
    let mut x = [0.0; 3];
    for (k, (name, part)) in ["START", "STOP", "STEP"].iter().zip(&parts).enumerate() {
        x[k] = part
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("{name} {part:?} of the range is not a finite number"))?;
    }
    let [start, stop, step] = x;
    if step == 0.0 {
        return Err("STEP of the range is 0; expected a non-zero step".into());
    }
    let q = (stop - start) / step;
    if q < -1.0e-9 {
        return Err(format!("STEP {step} leads away from STOP {stop}; use a step of the other sign"));
    }
    let nearest = q.round();
    let steps = if (q - nearest).abs() <= 1.0e-9 * nearest.max(1.0) { nearest } else { q.floor() };
    if steps.is_nan() || steps >= MAX_RANGE_VALUES as f64 {
        return Err(format!("the range has {:.0} values, more than {MAX_RANGE_VALUES}", steps + 1.0));
    }
    let decimals = parts.iter().map(|p| decimals(p)).max().unwrap_or(0);
    Ok((0..=steps as usize).map(|k| decimal(start + k as f64 * step, decimals)).collect())
}

/// Digits after the decimal point that `text` (a number) needs: `0.25` 2, `2.5e-3` 4, `1e5` 0.
fn decimals(text: &str) -> usize {
    let (mantissa, exponent) = match text.find(['e', 'E']) {
        Some(k) => (&text[..k], text[k + 1..].parse::<i64>().unwrap_or(0)),
        None => (text, 0),
    };
    let fraction = mantissa.find('.').map_or(0, |k| mantissa.len() - k - 1) as i64;
    (fraction - exponent).clamp(0, 30) as usize
}

/// `x` with `decimals` digits after the point, trailing zeros (and a trailing point) removed.
fn decimal(x: f64, decimals: usize) -> String {
    let mut s = format!("{x:.decimals$}");
    if s.contains('.') {
        s.truncate(s.trim_end_matches('0').trim_end_matches('.').len());
    }
    if s == "-0" { "0".into() } else { s }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn range(text: &str) -> Vec<String> {
        parse_range(text).unwrap()
    }

    #[test]
    fn ranges_are_inclusive_and_exact() {
        assert_eq!(range("10:30:5"), ["10", "15", "20", "25", "30"]);
        assert_eq!(range("0.1:0.3:0.1"), ["0.1", "0.2", "0.3"]);
        // (0.3 - 0) / 0.1 = 2.9999999999999996: the stop is still included
        assert_eq!(range("0:0.3:0.1"), ["0", "0.1", "0.2", "0.3"]);
        assert_eq!(range("0:1:0.1").len(), 11);
        assert_eq!(range("0:1:0.1")[7], "0.7");
        assert_eq!(range("10:31:5"), ["10", "15", "20", "25", "30"]);
        assert_eq!(range("30:10:-10"), ["30", "20", "10"]);
        assert_eq!(range("-1:1:1"), ["-1", "0", "1"]);
        assert_eq!(range("5:5:1"), ["5"]);
        assert_eq!(range("1e5:3e5:1e5"), ["100000", "200000", "300000"]);
        assert_eq!(range("0:5e-3:2.5e-3"), ["0", "0.0025", "0.005"]);
        assert_eq!(range(" 1 : 2 : 0.5 "), ["1", "1.5", "2"]);
        // every value reads back as the number a user would type
        for (k, v) in range("0:2:0.01").iter().enumerate() {
            let typed = format!("{}.{:02}", k / 100, k % 100).parse::<f64>().unwrap();
            assert_eq!(v.parse::<f64>().unwrap().to_bits(), typed.to_bits(), "{v}");
        }
    }

    #[test]
    fn bad_ranges_say_why() {
        for (text, reason) in [
            ("10:30", "three numbers"),
            ("10:30:5:1", "three numbers"),
            ("10:x:5", "STOP \"x\""),
            ("10:30:0", "STEP of the range is 0"),
            ("10:30:-5", "leads away"),
            ("0:1:1e-9", "more than"),
            ("0:inf:1", "not a finite number"),
        ] {
            let e = parse_range(text).unwrap_err();
            assert!(e.contains(reason), "{text}: {e}");
        }
    }

    #[test]
    fn lists_are_split_and_trimmed() {
        assert_eq!(parse_values("f", "10, 15 ,20").unwrap(), ["10", "15", "20"]);
        assert_eq!(parse_values("f", "tension_only,linear").unwrap(), ["tension_only", "linear"]);
        assert_eq!(parse_values("f", "ACSR Drake").unwrap(), ["ACSR Drake"]);
        assert_eq!(parse_values("f", "10:20:5").unwrap(), ["10", "15", "20"]);
        let e = parse_values("loads.wind.speed_m_per_s", "10,,20").unwrap_err();
        assert_eq!(
            e.to_string(),
            "--vary loads.wind.speed_m_per_s=10,,20: value 2 of the list is empty; expected a list \
             VALUE,VALUE,... or a range START:STOP:STEP"
        );
    }
}
