//! Shards: `--shard K/N` runs the cases `i` with `i mod N = K`, K counting from 0 (`0/10` to `9/10`, as
//! a Slurm job array `--array=0-9` numbers its tasks). Round-robin rather than contiguous blocks: cases
//! next to each other in the product often cost about the same (the last axis varies fastest), so every
//! shard gets a similar mix of cheap and expensive cases. A shard writes `sweep.K-of-N.csv` and
//! `sweep.K-of-N.json`; `ohl sweep merge` joins them.

use std::fmt;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

/// One of N deterministic slices of a sweep ([module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Shard {
    /// K, from 0
    pub index: usize,
    /// N, at least 1
    pub count: usize,
}

/// A `--shard` argument that is not `K/N` with `0 <= K < N`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("--shard {text}: {reason}")]
pub struct ShardError {
    /// the argument
    pub text: String,
    /// what is wrong
    pub reason: String,
}

impl FromStr for Shard {
    type Err = ShardError;

    fn from_str(text: &str) -> Result<Shard, ShardError> {
        let fail = |reason: String| ShardError { text: text.into(), reason };
        let (k, n) = text.split_once('/').ok_or_else(|| fail("expected K/N, e.g. 0/10 (K counts from 0)".into()))?;
        let whole = |s: &str, name: &str| {
            s.trim().parse::<usize>().map_err(|_| fail(format!("{name} = {s:?} is not a whole number >= 0")))
        };
        let (index, count) = (whole(k, "K")?, whole(n, "N")?);
        if count == 0 {
            return Err(fail("N must be at least 1".into()));
        }
        if index >= count {
            return Err(fail(format!(
                "K counts from 0 and must be below N: shards 0/{count} to {}/{count} (for a Slurm array \
                 numbered from 1, pass $((SLURM_ARRAY_TASK_ID - 1)))",
                count - 1
            )));
        }
        Ok(Shard { index, count })
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl Shard {
    /// The case ids of this shard among `cases`, in order.
    pub fn ids(&self, cases: usize) -> Vec<usize> {
        (self.index..cases).step_by(self.count).collect()
    }

    /// Whether case `id` belongs to this shard.
    pub fn holds(&self, id: usize) -> bool {
        id % self.count == self.index
    }

    /// The stem of this shard's files, `sweep.K-of-N`.
    pub fn stem(&self) -> String {
        format!("sweep.{}-of-{}", self.index, self.count)
    }

    /// The shard of a file name `sweep.K-of-N.csv`, if it is one.
    pub fn of_file_name(name: &str) -> Option<Shard> {
        let (k, n) = name.strip_prefix("sweep.")?.strip_suffix(".csv")?.split_once("-of-")?;
        let s = Shard { index: k.parse().ok()?, count: n.parse().ok()? };
        (s.index < s.count && s.stem() + ".csv" == name).then_some(s)
    }
}

/// The stem of a sweep's files: `sweep` or `sweep.K-of-N`.
pub fn stem(shard: Option<Shard>) -> String {
    shard.map_or_else(|| "sweep".to_string(), |s| s.stem())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_parse_and_partition_the_cases() {
        let s: Shard = "2/4".parse().unwrap();
        assert_eq!(s, Shard { index: 2, count: 4 });
        assert_eq!(s.ids(11), [2, 6, 10]);
        let mut all: Vec<usize> = (0..4).flat_map(|k| Shard { index: k, count: 4 }.ids(11)).collect();
        all.sort();
        assert_eq!(all, (0..11).collect::<Vec<_>>());
        assert!(s.holds(6) && !s.holds(7));
        assert_eq!(s.stem(), "sweep.2-of-4");
        assert_eq!(Shard::of_file_name("sweep.2-of-4.csv"), Some(s));
        assert_eq!(Shard::of_file_name("sweep.4-of-4.csv"), None);
        assert_eq!(Shard::of_file_name("sweep.02-of-4.csv"), None);
        assert_eq!(Shard::of_file_name("sweep.csv"), None);
        assert_eq!("0/1".parse::<Shard>().unwrap().ids(3), [0, 1, 2]);
    }

    #[test]
    fn bad_shards_say_why() {
        for (text, reason) in [
            ("3", "expected K/N"),
            ("10/10", "must be below N: shards 0/10 to 9/10"),
            ("1/0", "at least 1"),
            ("-1/4", "K = \"-1\""),
            ("a/4", "not a whole number"),
        ] {
            let e = text.parse::<Shard>().unwrap_err().to_string();
            assert!(e.contains(reason), "{text}: {e}");
        }
    }
}
