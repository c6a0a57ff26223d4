//! A CSV file that only ever holds whole rows.
//!
//! The header is written to a temporary file that is then renamed into place, so the file never exists
//! without its header. Rows are formatted in memory and appended with one `write` call per
//! [`RowFile::commit`] (a sample, or a whole snapshot), so a run killed between two commits leaves only
//! whole rows; the buffer is never flushed part-way. Numbers are written in the shortest form that reads
//! back to the same `f64` (`ryu`).

use std::fs::{File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};

/// An append-only CSV file of numeric rows.
pub struct RowFile {
    file: File,
    path: PathBuf,
    pending: Vec<u8>,
    columns: usize,
    fields: usize,
}

impl RowFile {
    /// Create `path` with the given header (replacing any earlier file).
    pub fn create(path: &Path, header: &[String]) -> std::io::Result<Self> {
        let tmp = path.with_extension("csv.partial");
        {
            let mut f = File::create(&tmp)?;
            f.write_all((header.join(",") + "\n").as_bytes())?;
        }
        std::fs::rename(&tmp, path)?;
        let file = OpenOptions::new().append(true).open(path)?;
        Ok(RowFile { file, path: path.to_path_buf(), pending: Vec::new(), columns: header.len(), fields: 0 })
    }

    /// The file's path.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Append a number to the current row.
    pub fn number(&mut self, x: f64) {
        self.separator();
        let mut b = ryu::Buffer::new();
        self.pending.extend_from_slice(b.format(x).as_bytes());
    }

    /// Append an integer to the current row.
    pub fn integer(&mut self, x: u64) {
        self.separator();
        self.pending.extend_from_slice(x.to_string().as_bytes());
    }

    fn separator(&mut self) {
        if self.fields > 0 {
            self.pending.push(b',');
        }
        self.fields += 1;
    }

    /// End the current row. Panics if it does not have one field per column (internal misuse).
    pub fn end_row(&mut self) {
        assert_eq!(self.fields, self.columns, "{}: a row needs one field per column", self.path.display());
        self.pending.push(b'\n');
        self.fields = 0;
    }

    /// Write the rows ended since the last commit, in one call.
    pub fn commit(&mut self) -> std::io::Result<()> {
        assert_eq!(self.fields, 0, "commit inside a row");
        if !self.pending.is_empty() {
            self.file.write_all(&self.pending)?;
            self.pending.clear();
        }
        Ok(())
    }
}

/// Write `text` to `path` whole or not at all: a temporary file renamed into place.
pub fn write_atomically(path: &Path, text: &str) -> std::io::Result<()> {
    let tmp = path.with_extension("partial");
    std::fs::write(&tmp, text)?;
    std::fs::rename(&tmp, path)
}
