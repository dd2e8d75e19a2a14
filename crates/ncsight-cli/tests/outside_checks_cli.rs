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
