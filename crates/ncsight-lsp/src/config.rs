//! Which controller a document is for, and the run's settings (docs/reference/interface.md,
//! third round): the first line's `(ncsight: MACHINE)`, else `ncsight.toml` in the file's folder
//! or a parent (`machine`, `setup`, `params`, `subprogram_dirs`, paths relative to that file),
//! else the client's setting `ncsight.machine`, else gsk980tdi. The document's own folder is
//! always searched for called programmes.

use serde::Deserialize;
use std::path::{Path, PathBuf};

/// The file beside the programmes that says how they run.
pub const CONFIG_FILE: &str = "ncsight.toml";

/// How a document is run.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RunConfig {
    pub machine: String,
    /// Where the machine came from, as the hover says it.
    pub from: String,
    /// `N=V` overrides.
    pub params: Vec<String>,
    pub setup: Option<PathBuf>,
    pub subprogram_dirs: Vec<PathBuf>,
    /// A mistake in `ncsight.toml` (shown as a diagnostic on the first line).
    pub problem: Option<String>,
}

#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct ConfigFile {
    machine: Option<String>,
    setup: Option<String>,
    #[serde(default)]
    params: toml::Table,
    #[serde(default)]
    subprogram_dirs: Vec<String>,
}

/// The `ncsight.toml` nearest to `folder` (the folder itself, then its parents).
pub fn find_config(folder: &Path) -> Option<PathBuf> {
    folder.ancestors().map(|d| d.join(CONFIG_FILE)).find(|p| p.is_file())
}

/// The run's settings for a document at `path` (None: not a file on disk) whose text is `text`,
/// with the client's `setting` for the machine.
pub fn for_document(path: Option<&Path>, text: &[u8], setting: Option<&str>) -> RunConfig {
    let folder = path.and_then(Path::parent);
    let mut cfg = RunConfig::default();
    if let Some(file) = folder.and_then(find_config) {
        read_config(&file, &mut cfg);
    }
    if let Some(dir) = folder {
        if !cfg.subprogram_dirs.iter().any(|d| d == dir) {
            cfg.subprogram_dirs.push(dir.to_path_buf());
        }
    }
    if let Some(name) = ncsight_io::machine_from_first_line(text) {
        cfg.machine = name;
        cfg.from = "the first line's (ncsight: ...)".into();
    } else if cfg.machine.is_empty() {
        match setting.filter(|s| !s.trim().is_empty()) {
            Some(s) => (cfg.machine, cfg.from) = (s.trim().to_string(), "the editor's setting ncsight.machine".into()),
            None => (cfg.machine, cfg.from) = ("gsk980tdi".into(), "the default (no first line, ncsight.toml or setting names one)".into()),
        }
    }
    // The profile's own spelling (`GSK980TDi` names gsk980tdi): the tables hover and
    // definitions read are by that name.
    if let Some(p) = ncsight::profile::by_name(&cfg.machine) {
        cfg.machine = p.name.to_string();
    }
    cfg
}

fn read_config(file: &Path, cfg: &mut RunConfig) {
    let base = file.parent().unwrap_or(Path::new("."));
    let parsed: Result<ConfigFile, String> =
        std::fs::read_to_string(file).map_err(|e| e.to_string()).and_then(|t| toml::from_str(&t).map_err(|e| e.to_string()));
    let c = match parsed {
        Ok(c) => c,
        Err(e) => {
            cfg.problem = Some(format!("{}: {e}", file.display()));
            return;
        }
    };
    if let Some(m) = c.machine {
        cfg.machine = m;
        cfg.from = format!("{}", file.display());
    }
    cfg.setup = c.setup.map(|s| base.join(s));
    cfg.subprogram_dirs = c.subprogram_dirs.iter().map(|d| base.join(d)).collect();
    for (key, value) in c.params {
        let v = match value {
            toml::Value::Integer(i) => i.to_string(),
            toml::Value::Float(f) => f.to_string(),
            toml::Value::Boolean(b) => u8::from(b).to_string(),
            toml::Value::String(s) => s,
            other => {
                cfg.problem = Some(format!("{}: params.{key} = {other}: expected a number", file.display()));
                continue;
            }
        };
        cfg.params.push(format!("{key}={v}"));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_line_then_the_file_then_the_setting() {
        let dir = std::env::temp_dir().join(format!("ncsight-lsp-config-{}", std::process::id()));
        let sub = dir.join("parts");
        std::fs::create_dir_all(&sub).unwrap();
        let prog = sub.join("a.nc");
        assert_eq!(for_document(Some(&prog), b"G0 X1\n", Some("fanuc0t")).machine, "fanuc0t");
        assert_eq!(for_document(Some(&prog), b"G0 X1\n", None).machine, "gsk980tdi");
        std::fs::write(dir.join(CONFIG_FILE), "machine = \"fanuc0m\"\nparams = { \"5114\" = 2 }\nsubprogram_dirs = [\"lib\"]\n").unwrap();
        let c = for_document(Some(&prog), b"G0 X1\n", Some("fanuc0t"));
        assert_eq!((c.machine.as_str(), c.params.clone()), ("fanuc0m", vec!["5114=2".to_string()]));
        assert_eq!(c.subprogram_dirs, [dir.join("lib"), sub.clone()]);
        assert_eq!(for_document(Some(&prog), b"(ncsight: yasnac-lx3)\nG0 X1\n", None).machine, "yasnac-lx3");
        std::fs::write(dir.join(CONFIG_FILE), "machin = 1\n").unwrap();
        assert!(for_document(Some(&prog), b"", None).problem.unwrap().contains("machin"));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
