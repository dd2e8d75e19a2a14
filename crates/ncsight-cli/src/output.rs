//! Output files: never the input file, and never truncated before there is something to write
//! (`ncsight run o0012.nc -o o0012.nc` used to leave an empty programme).

use std::fs::File;
use std::io::{self, BufWriter, Write};

/// Whether two paths name the same file (the same device and inode, or on Windows the same
/// volume and file index: a link, `./a.nc` and `a.nc`, or another spelling of the path all
/// count). A path that does not exist yet is no input.
pub fn same_file(a: &str, b: &str) -> bool {
    if a == "-" || b == "-" {
        return false;
    }
    same_file::is_same_file(a, b).unwrap_or(false)
}

/// A file created at its first write (or at the final flush), so that a run that fails before
/// it has anything to say leaves an existing file as it was.
pub struct LazyFile {
    path: String,
    file: Option<BufWriter<File>>,
    capacity: usize,
}

impl LazyFile {
    /// `path` for output; an error when it is one of `inputs` (every file the run may read: the
    /// programme, the setup, the files of the subprogramme folders), checked before anything is
    /// written.
    pub fn new<S: AsRef<str>>(path: &str, inputs: &[S], capacity: usize) -> Result<LazyFile, String> {
        if let Some(i) = inputs.iter().map(AsRef::as_ref).find(|i| same_file(path, i)) {
            return Err(format!("the output {path} is {i}, a file this run reads: refusing to overwrite it"));
        }
        Ok(LazyFile { path: path.to_string(), file: None, capacity })
    }

    fn file(&mut self) -> io::Result<&mut BufWriter<File>> {
        if self.file.is_none() {
            let f = File::create(&self.path).map_err(|e| io::Error::new(e.kind(), format!("cannot write {}: {e}", self.path)))?;
            self.file = Some(BufWriter::with_capacity(self.capacity, f));
        }
        Ok(self.file.as_mut().expect("just created"))
    }
}

impl Write for LazyFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.file()?.write(buf)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.file()?.flush()
    }
}
