//! Defects found by outside checks in the third round (issue 32), through the command line:
//! each test failed before its fix.

mod common;

use std::path::PathBuf;

/// A folder of its own under the system's temporary folder, removed when dropped.
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Scratch {
        let p = std::env::temp_dir().join(format!("ncsight-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&p);
        std::fs::create_dir_all(&p).unwrap();
        Scratch(p)
    }

    fn file(&self, name: &str, text: &str) -> String {
        let p = self.0.join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    }

    fn path(&self, name: &str) -> String {
        self.0.join(name).to_str().unwrap().to_string()
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// A Ø40 shaft roughed with G71, finished with G70 and threaded M20x2.5, simulated without
/// `--stock`: the stock is guessed from the cuts (Ø40.5, the roughing's allowance, by 65 mm:
/// Z0 to 5 mm behind the deepest cut at Z-60) and said to be guessed; no chuck finding. The old
/// guess took the thread alone (Ø20.87 x 27 mm) and found four chucks that are not there.
const SHAFT: &str = "O0040\nG99 M03 S800 T0101\nG00 X42. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.5 W0.1 F0.2\nN10 G00 X16.\nG01 Z0.\nX19.8 Z-2.\nZ-25.\nX30.\nZ-45.\nX40.\nN20 Z-60.\nG70 P10 Q20\nG00 X100. Z100.\nT0303\nG00 X22. Z5.\nG92 X19.2 Z-22. F2.5\nX18.6\nX18.1\nX17.8\nG00 X100. Z100.\nM30\n";

#[test]
fn simulate_without_stock_guesses_it_from_the_cuts_and_says_so() {
    let dir = Scratch::new("guess");
    let f = dir.file("shaft.nc", SHAFT);
    let (code, out, err) = common::ncsight(&["simulate", &f, "-m", "gsk980tdi"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("stock guessed          40.5 x 65 mm from Z0 (guessed from the programme's cuts"), "{out}");
    assert!(!out.contains("chuck") && out.contains("findings               none"), "{out}");
    let (_, json, _) = common::ncsight(&["simulate", &f, "-m", "gsk980tdi", "--format", "json"]);
    assert!(json.contains("\"stock_guessed\":{\"diameter_mm\":40.5,\"length_mm\":65,\"front_z_mm\":0,\"bore_mm\":0}"), "{json}");
    // Given, it is not a guess; a stock too short meets the chuck, said plainly.
    let (code, out, _) = common::ncsight(&["simulate", &f, "-m", "gsk980tdi", "--stock", "42x30"]);
    assert_eq!(code, 3, "{out}");
    assert!(!out.contains("stock guessed") && out.contains("chuck") && !out.contains("against a guessed stock"), "{out}");
}

/// No output may be a file the run reads: a subprogramme file of `--subprogram-dir`, the setup
/// (`-o`, `--image`, for run, expand, simulate and report alike). Refused with exit 2 before
/// anything is written; the files stay as they were.
#[test]
fn outputs_never_overwrite_a_subprogramme_or_the_setup() {
    let dir = Scratch::new("outputs");
    let main = dir.file("main.nc", "G97 S500 M03\nG00 X40. Z2.\nM98 P1234\nM30\n");
    std::fs::create_dir_all(dir.path("sd")).unwrap();
    let sub_text = "O1234\nG01 X30. Z-10. F100\nM99\n";
    let sub = dir.file("sd/O1234.nc", sub_text);
    let setup_text = "[stock]\ndiameter_mm = 60.0\nlength_mm = 80.0\n";
    let setup = dir.file("s.toml", setup_text);
    let sd = dir.path("sd");
    let cases: Vec<Vec<&str>> = vec![
        vec!["run", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd, "-o", &sub],
        vec!["expand", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd, "--to", "linuxcnc", "-o", &sub],
        vec!["report", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd, "-o", &sub],
        vec!["run", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd, "--setup", &setup, "-o", &setup],
        vec!["simulate", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd, "--setup", &setup, "--image", &setup],
        vec!["report", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd, "--setup", &setup, "-o", &setup],
    ];
    for args in cases {
        let (code, _, err) = common::ncsight(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains("a file this run reads: refusing to overwrite it"), "{args:?}: {err}");
        assert_eq!(std::fs::read_to_string(&sub).unwrap(), sub_text, "{args:?} changed the subprogramme");
        assert_eq!(std::fs::read_to_string(&setup).unwrap(), setup_text, "{args:?} changed the setup");
    }
    // Another file in the folder is fine.
    let other = dir.path("sd/out.txt");
    let (code, _, err) = common::ncsight(&["run", &main, "-m", "gsk980tdi", "--subprogram-dir", &sd, "-o", &other]);
    assert_eq!(code, 0, "{err}");
}
