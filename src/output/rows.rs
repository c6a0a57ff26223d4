//! A CSV file that only ever holds whole rows, even when the process is killed (SIGKILL) at any moment.
//!
//! - The header is written to a temporary file that is then renamed into place, so the file never exists
//!   without its header.
//! - Rows are formatted in memory and reach the file one page (4096 bytes of the file) at a time, each
//!   page in one `write` call that lies within that page. Linux honours a fatal signal only between the
//!   pages of a write (`generic_perform_write` checks for it before copying each page), so such a write
//!   lands whole or not at all. A page holds whole rows only: the rows of a page are padded to end exactly
//!   at the page boundary by trailing zeros in the mantissa of their first finite number (`1.25` becomes
//!   `1.2500`, `1.0e-7` becomes `1.000e-7`: the same `f64` for every CSV reader).
//! - Rows that do not fill a page yet are held in memory until they do, or until [`RowFile::finish`]
//!   writes them (one write within the last page). A killed run loses at most those rows.
//! - A row longer than a page, or a header that leaves no room for the next row in its page, cannot be
//!   written this way; such rows are written as they come (documented limit: several hundred columns).
//!
//! Numbers are written in the shortest form that reads back to the same `f64` (`ryu`), always with a
//! decimal point.

use std::fs::{File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};

/// Bytes per page of the file: the unit the kernel writes atomically with respect to a fatal signal.
const PAGE: usize = 4096;

/// An append-only CSV file of numeric rows.
pub struct RowFile {
    file: File,
    path: PathBuf,
    /// bytes in the file so far
    len: usize,
    /// formatted rows not yet written
    pending: Vec<u8>,
    /// start of each pending row in `pending`, and where zeros may be inserted in it
    rows: Vec<(usize, Option<usize>)>,
    columns: usize,
    fields: usize,
    page: Vec<u8>,
}

impl RowFile {
    /// Create `path` with the given header (replacing any earlier file).
    pub fn create(path: &Path, header: &[String]) -> std::io::Result<Self> {
        let tmp = path.with_extension("csv.partial");
        let head = header.join(",") + "\n";
        {
            let mut f = File::create(&tmp)?;
            f.write_all(head.as_bytes())?;
        }
        std::fs::rename(&tmp, path)?;
        let file = OpenOptions::new().append(true).open(path)?;
        Ok(RowFile {
            file,
            path: path.to_path_buf(),
            len: head.len(),
            pending: Vec::new(),
            rows: Vec::new(),
            columns: header.len(),
            fields: 0,
            page: Vec::with_capacity(PAGE),
        })
    }

    /// The file's path.
    pub fn path(&self) -> &Path {
        &self.path
    }

    fn separator(&mut self) {
        if self.fields == 0 {
            self.rows.push((self.pending.len(), None));
        } else {
            self.pending.push(b',');
        }
        self.fields += 1;
    }

    /// Append a number to the current row.
    pub fn number(&mut self, x: f64) {
        self.separator();
        let mut b = ryu::Buffer::new();
        let text = b.format(x).as_bytes();
        if !x.is_finite() {
            self.pending.extend_from_slice(text);
            return;
        }
        // Always a decimal point (`1e-7` -> `1.0e-7`), so that zeros can be appended to the mantissa.
        let e = text.iter().position(|&c| c == b'e').unwrap_or(text.len());
        self.pending.extend_from_slice(&text[..e]);
        if !text[..e].contains(&b'.') {
            self.pending.extend_from_slice(b".0");
        }
        let pad_at = self.pending.len();
        self.pending.extend_from_slice(&text[e..]);
        let row = self.rows.last_mut().expect("separator opened the row");
        row.1 = row.1.or(Some(pad_at));
    }

    /// Append an integer to the current row.
    pub fn integer(&mut self, x: u64) {
        self.separator();
        self.pending.extend_from_slice(x.to_string().as_bytes());
    }

    /// End the current row. Panics if it does not have one field per column (internal misuse).
    pub fn end_row(&mut self) {
        assert_eq!(self.fields, self.columns, "{}: a row needs one field per column", self.path.display());
        self.pending.push(b'\n');
        self.fields = 0;
    }

    fn row_bytes(&self, k: usize) -> (usize, usize) {
        let start = self.rows[k].0;
        let end = self.rows.get(k + 1).map_or(self.pending.len(), |r| r.0);
        (start, end)
    }

    fn write(&mut self, bytes: &[u8]) -> std::io::Result<()> {
        self.file.write_all(bytes)?;
        self.len += bytes.len();
        Ok(())
    }

    /// Write every page that the rows ended so far fill; the rest waits for more rows or for
    /// [`RowFile::finish`].
    pub fn commit(&mut self) -> std::io::Result<()> {
        assert_eq!(self.fields, 0, "commit inside a row");
        let n = self.rows.len();
        let mut k = 0;
        while k < n {
            let room = PAGE - self.len % PAGE;
            let (mut end, mut bytes) = (k, 0);
            while end < n {
                let (a, b) = self.row_bytes(end);
                if bytes + (b - a) > room {
                    break;
                }
                bytes += b - a;
                end += 1;
            }
            if end == n {
                break; // the rows left do not fill this page: keep them
            }
            if end == k {
                // The next row does not fit in what is left of this page and no row can be padded to
                // fill it (a row longer than a page, or a long header): write it as it comes.
                let (a, b) = self.row_bytes(k);
                let row = self.pending[a..b].to_vec();
                self.write(&row)?;
                k += 1;
                continue;
            }
            // Rows k..end fill the page up to `room - bytes`: pad them to end on the boundary, the gap
            // shared out exactly (`gap / paddable` zeros each, one more for the first `gap % paddable`).
            let gap = room - bytes;
            let paddable = (k..end).filter(|&r| self.rows[r].1.is_some()).count();
            let (base, extra) = gap.checked_div(paddable).map_or((0, 0), |b| (b, gap % paddable));
            let mut page = std::mem::take(&mut self.page);
            page.clear();
            let mut padded = 0;
            for r in k..end {
                let (a, b) = self.row_bytes(r);
                match self.rows[r].1 {
                    Some(p) => {
                        let share = base + usize::from(padded < extra);
                        padded += 1;
                        page.extend_from_slice(&self.pending[a..p]);
                        page.resize(page.len() + share, b'0');
                        page.extend_from_slice(&self.pending[p..b]);
                    }
                    None => page.extend_from_slice(&self.pending[a..b]),
                }
            }
            debug_assert!(paddable == 0 || page.len() == room, "a padded page ends on the boundary");
            let result = self.write(&page);
            self.page = page;
            result?;
            k = end;
        }
        if k > 0 {
            let cut = self.rows.get(k).map_or(self.pending.len(), |r| r.0);
            self.pending.drain(..cut);
            self.rows.drain(..k);
            for r in &mut self.rows {
                r.0 -= cut;
                r.1 = r.1.map(|p| p - cut);
            }
        }
        Ok(())
    }

    /// Write the rows still held (one write within the last page).
    pub fn finish(&mut self) -> std::io::Result<()> {
        self.commit()?;
        let tail = std::mem::take(&mut self.pending);
        self.rows.clear();
        self.write(&tail)
    }
}

/// Write `text` to `path` whole or not at all: a temporary file renamed into place.
pub fn write_atomically(path: &Path, text: &str) -> std::io::Result<()> {
    let tmp = path.with_extension("partial");
    std::fs::write(&tmp, text)?;
    std::fs::rename(&tmp, path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pages_hold_whole_rows_and_numbers_read_back_exactly() {
        let dir = std::env::temp_dir().join(format!("ohl-rows-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("t.csv");
        let header: Vec<String> = ["a", "b", "n"].map(String::from).into();
        let mut f = RowFile::create(&path, &header).unwrap();
        let mut expected = Vec::new();
        for i in 0..3000_u64 {
            let (a, b) = (1.0 / (i as f64 + 3.0), (i as f64) * 1.0e-9);
            f.number(a);
            f.number(b);
            f.integer(i);
            f.end_row();
            expected.push((a, b, i));
            if i % 7 == 0 {
                f.commit().unwrap();
                // Everything written so far is whole pages of whole rows after the header.
                let text = std::fs::read_to_string(&path).unwrap();
                assert!(text.ends_with('\n'));
            }
        }
        f.finish().unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some("a,b,n"));
        let mut offset = 6;
        for (line, (a, b, i)) in lines.zip(&expected) {
            let v: Vec<&str> = line.split(',').collect();
            assert_eq!(v[0].parse::<f64>().unwrap().to_bits(), a.to_bits(), "{line}");
            assert_eq!(v[1].parse::<f64>().unwrap().to_bits(), b.to_bits(), "{line}");
            assert_eq!(v[2].parse::<u64>().unwrap(), *i);
            // No row crosses a page boundary of the file.
            let end = offset + line.len() + 1;
            assert!(offset / PAGE == (end - 1) / PAGE, "row {i} crosses a page: {offset}..{end}");
            offset = end;
        }
        assert_eq!(text.lines().count(), 3001);
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn long_rows_of_many_numbers_never_cross_a_page() {
        // Rows of eleven numbers (about 150 bytes, like snapshots.csv): the gap at the end of a page can
        // exceed the number of rows in it, and must still be shared out exactly.
        let dir = std::env::temp_dir().join(format!("ohl-rows-long-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("t.csv");
        let header: Vec<String> = (0..11).map(|k| format!("c{k}")).collect();
        let mut f = RowFile::create(&path, &header).unwrap();
        for i in 0..5000_u64 {
            for k in 0..11 {
                f.number((i as f64 + 0.1) * 1.234_567_891_234e-3 * (k as f64 + 1.0) - 7.0);
            }
            f.end_row();
            if i % 13 == 0 {
                f.commit().unwrap();
            }
        }
        f.finish().unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        let mut offset = 0;
        for (i, line) in text.lines().enumerate() {
            let end = offset + line.len() + 1;
            if i > 0 {
                assert!(offset / PAGE == (end - 1) / PAGE, "row {i} crosses a page: {offset}..{end}");
                assert_eq!(line.split(',').count(), 11);
            }
            offset = end;
        }
        assert_eq!(text.lines().count(), 5001);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
