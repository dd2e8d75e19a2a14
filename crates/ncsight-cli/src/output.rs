//! Output files: never the input file, and never truncated before there is something to write
//! (`ncsight run o0012.nc -o o0012.nc` used to leave an empty programme).

use std::fs::File;
use std::io::{self, BufWriter, Write};

/// Whether two paths name the same file (the same device and inode: a link, `./a.nc` and
/// `a.nc`, or another spelling of the path all count).
pub fn same_file(a: &str, b: &str) -> bool {
    if a == "-" || b == "-" {
        return false;
    }
    match (std::fs::metadata(a), std::fs::metadata(b)) {
        (Ok(x), Ok(y)) => {
            #[cfg(unix)]
            {
                use std::os::unix::fs::MetadataExt;
                x.dev() == y.dev() && x.ino() == y.ino()
            }
            #[cfg(not(unix))]
            {
                let _ = (x, y);
                matches!((std::fs::canonicalize(a), std::fs::canonicalize(b)), (Ok(p), Ok(q)) if p == q)
            }
        }
        _ => false,
    }
}

/// A file created at its first write (or at the final flush), so that a run that fails before
/// it has anything to say leaves an existing file as it was.
pub struct LazyFile {
    path: String,
    file: Option<BufWriter<File>>,
    capacity: usize,
}

impl LazyFile {
    /// `path` for output; an error when it is one of `inputs`.
    pub fn new(path: &str, inputs: &[&str], capacity: usize) -> Result<LazyFile, String> {
        if let Some(i) = inputs.iter().find(|i| same_file(path, i)) {
            return Err(format!("the output {path} is the input file {i}: refusing to overwrite the programme"));
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
