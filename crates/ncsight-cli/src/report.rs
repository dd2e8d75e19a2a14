//! The page of `ncsight app` and `ncsight report`: one self-contained HTML file (styles, script,
//! the engine in WebAssembly, no network request of any kind) that runs a programme in the
//! browser and shows what it does. `app` writes it empty; `report` writes it with a programme,
//! its controller, parameters, setup and operator settings, which the page runs on opening (the
//! page holds the programme, not a dump of its motions), and the thread form measured by the
//! stock simulation when there is one.
//!
//! Programme text is untrusted: it goes into the page only as JSON inside a
//! `<script type="application/json">` element, with `<`, `>` and `&` written as `\u` escapes, and
//! the page's script puts it into the document as text (a textarea's value, `textContent`),
//! never as markup.

use crate::format::jsonl::json_str;
use crate::format::num;
use ncsight::stock::measure::Simulation;
use std::fmt::Write as _;
use std::io::{self, Write};

/// The engine: crates/ncsight-wasm built for wasm32-unknown-unknown by build.rs (empty when the
/// Rust target was missing at build time).
const ENGINE: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/engine.wasm"));

/// Why no page can be written: the engine was not built into this binary.
pub fn engine_missing() -> Option<&'static str> {
    ENGINE.is_empty().then_some("this ncsight was built without the page's engine: run `rustup target add wasm32-unknown-unknown`, then build ncsight again")
}

/// A programme for the page to open with (`ncsight report`).
pub struct Preload<'a> {
    pub file_name: &'a str,
    /// The programme as the page's editor shows it (lines that are not UTF-8 decoded as
    /// `--encoding` says; the engine reads the comments' text the same either way).
    pub text: String,
    pub machine: &'a str,
    pub params: &'a [String],
    /// The setup file's TOML text.
    pub setup: Option<String>,
    pub options: &'a ncsight::Options,
    pub switches: ncsight::Switches,
    /// Lines of the operator settings the page passes on unchanged (`main=`, `var=`, ...).
    pub extra_options: Vec<String>,
    pub stock: Option<ncsight::setup::Bar>,
    /// The thread it should make (`--expect`), drawn over the measured section.
    pub expect: Option<&'a ncsight::stock::standard::Expected>,
    /// Files where called programmes are looked for (name, text).
    pub library: Vec<(String, String)>,
    /// The run's options and switches, described.
    pub settings: Vec<String>,
    /// The file's bytes as read: the page saves them back unchanged while the text is not edited.
    pub original: &'a [u8],
    /// The encoding of its lines that are not UTF-8 (`gb18030` unless `--encoding` said).
    pub encoding: &'static str,
    pub sim: Option<&'a Simulation>,
    /// Why the thread could not be simulated, when it could not.
    pub sim_error: Option<&'a str>,
}

fn esc_html(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// JSON safe inside a script element: no `<`, `>` or `&` at all.
fn script_safe(json: &str) -> String {
    json.replace('<', "\\u003c").replace('>', "\\u003e").replace('&', "\\u0026")
}

/// The job the page starts with, as JSON.
fn job_json(p: Option<&Preload>) -> String {
    let machines: Vec<String> = ncsight::profile::all().iter().map(|m| format!("[{},{},{}]", json_str(m.name), json_str(m.title), m.is_lathe())).collect();
    let mut s = format!("{{\"machines\":[{}],\"explain\":{}", machines.join(","), explanations_json());
    let Some(p) = p else {
        s.push('}');
        return s;
    };
    let strs = |v: &[String]| v.iter().map(|x| json_str(x)).collect::<Vec<_>>().join(",");
    let o = p.options;
    let _ = write!(
        s,
        ",\"file\":{},\"machine\":{},\"text\":{},\"params\":[{}],\"setup\":{},\"settings\":[{}]",
        json_str(p.file_name),
        json_str(p.machine),
        json_str(&p.text),
        strs(p.params),
        json_str(p.setup.as_deref().unwrap_or("")),
        strs(&p.settings)
    );
    // The bytes as opened, when the text alone does not give them back (a byte-order mark, CR LF
    // line ends, lines in GBK): the page's download writes them unchanged, or an edited text
    // in the same form.
    if p.original != p.text.as_bytes() {
        let utf8 = std::str::from_utf8(p.original).is_ok();
        let _ = write!(
            s,
            ",\"original\":{{\"base64\":\"{}\",\"encoding\":\"{}\",\"crlf\":{},\"bom\":{}}}",
            base64(p.original),
            if utf8 { "utf-8" } else { p.encoding },
            p.original.windows(2).any(|w| w == b"\r\n"),
            p.original.starts_with(&[0xEF, 0xBB, 0xBF])
        );
    }
    let holds: Vec<String> = o.feed_hold_at.iter().map(|t| num(*t, 4)).collect();
    let _ = write!(
        s,
        ",\"options\":{{\"single_block\":{},\"dry_run\":{},\"block_delete\":{},\"optional_stop\":{},\"feed_override\":{},\"rapid_override\":{},\"feed_hold_at\":[{}],\"reset_at\":{},\"extra\":{}}}",
        o.single_block,
        o.overrides.dry_run,
        p.switches.block_delete,
        p.switches.optional_stop,
        num(o.overrides.feed_pct, 3),
        num(o.overrides.rapid_pct, 3),
        holds.join(","),
        o.reset_at.map(|t| num(t, 4)).unwrap_or_else(|| "null".into()),
        json_str(&p.extra_options.join("\n"))
    );
    if let Some(b) = p.stock {
        let _ =
            write!(s, ",\"stock\":{{\"diameter_mm\":{},\"length_mm\":{},\"front_z_mm\":{}}}", num(b.diameter_mm, 4), num(b.length_mm, 4), num(b.front_z_mm, 4));
    }
    if let Some(e) = p.expect {
        let _ = write!(
            s,
            ",\"expect\":{{\"name\":{},\"major_mm\":{},\"minor_mm\":{},\"pitch_mm\":{}}}",
            json_str(&e.name),
            num(e.major_mm, 4),
            num(e.minor_mm, 4),
            num(e.pitch_mm, 4)
        );
    }
    let lib: Vec<String> = p.library.iter().map(|(n, t)| format!("[{},{}]", json_str(n), json_str(t))).collect();
    let _ = write!(s, ",\"library\":[{}]", lib.join(","));
    match p.sim {
        Some(sim) => {
            let _ = write!(s, ",\"sim\":{}", crate::simulate::json(&sim.measurement).trim_end());
            // The axial section at angle 0, X as a diameter, at most 4000 points.
            let g = sim.stock.grid;
            let row = sim.stock.row(0);
            let step = g.nz.div_ceil(4000).max(1);
            let section: Vec<String> = (0..g.nz).step_by(step).map(|i| format!("[{},{}]", num(g.z(i), 4), num(2.0 * row[i] as f64, 4))).collect();
            let _ = write!(s, ",\"section\":[{}]", section.join(","));
            let mut png = Vec::new();
            if crate::simulate::image(sim, &mut png).is_ok() {
                let _ = write!(s, ",\"unrolled\":\"data:image/png;base64,{}\"", base64(&png));
            }
        }
        None => {
            if let Some(e) = p.sim_error {
                let _ = write!(s, ",\"sim_error\":{}", json_str(e));
            }
        }
    }
    s.push('}');
    s
}

/// Every code's explanation (`ncsight explain`'s catalogue) for the page, by project code:
/// severity, the controller's FANUC number where it has one, the title in English and Chinese,
/// then meaning, causes and fix as `[English, Chinese]`, and the wrong and right examples.
fn explanations_json() -> String {
    let Ok(all) = ncsight::explain::catalogue() else { return "{}".into() };
    let pair = |en: &str, zh: &str| format!("[{},{}]", json_str(en), json_str(zh));
    let list = |v: &[String]| format!("[{}]", v.iter().map(|x| json_str(x)).collect::<Vec<_>>().join(","));
    let rows: Vec<String> = all
        .iter()
        .filter_map(|(code, e)| {
            let rule = ncsight::explain::rule_of(code)?;
            let sev = if rule.severity() == ncsight::Severity::Alarm { "alarm" } else { "warning" };
            Some(format!(
                "{}:{{\"sev\":\"{sev}\",\"fanuc\":{},\"title\":{},\"meaning\":{},\"causes\":[{},{}],\"fix\":{},\"wrong\":{},\"right\":{},\"profile\":{}}}",
                json_str(code),
                rule.fanuc_code().map(json_str).unwrap_or_else(|| "null".into()),
                pair(rule.title(), &e.title_zh),
                pair(&e.meaning_en, &e.meaning_zh),
                list(&e.causes_en),
                list(&e.causes_zh),
                pair(&e.fix_en, &e.fix_zh),
                json_str(&e.wrong),
                json_str(&e.right),
                json_str(&e.profile)
            ))
        })
        .collect();
    format!("{{{}}}", rows.join(","))
}

/// Write the page: empty (`app`) or opening with `preload` (`report`).
pub fn write(preload: Option<&Preload>, w: &mut dyn Write) -> io::Result<()> {
    let title = esc_html(&match preload {
        Some(p) => format!("ncsight: {}", p.file_name),
        None => "ncsight".to_string(),
    });
    write!(
        w,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src data:; style-src 'unsafe-inline'; script-src 'unsafe-inline' 'wasm-unsafe-eval'; worker-src blob:\">\n\
         <title>{title}</title>\n<style>{}</style></head>\n<body>\n{}\n\
         <script type=\"application/json\" id=\"ncsight-job\">{}</script>\n<script type=\"application/octet-stream\" id=\"ncsight-engine\">",
        include_str!("app/style.css"),
        include_str!("app/body.html"),
        script_safe(&job_json(preload))
    )?;
    // The engine, base64 in lines of 76 (the page decodes it once).
    let b64 = base64(ENGINE);
    for chunk in b64.as_bytes().chunks(76 * 1024) {
        w.write_all(chunk)?;
    }
    // three.js (its licence in its opening comment) for the 3D view of the cut stock, then the page.
    write!(w, "</script>\n<script>{}</script>\n<script>{}</script>\n</body></html>\n", include_str!("app/three/three.min.js"), include_str!("app/app.js"))
}

/// Standard base64 (RFC 4648) for the inline engine and image.
fn base64(bytes: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for c in bytes.chunks(3) {
        let n = (c[0] as u32) << 16 | (*c.get(1).unwrap_or(&0) as u32) << 8 | *c.get(2).unwrap_or(&0) as u32;
        out.push(A[(n >> 18) as usize & 63] as char);
        out.push(A[(n >> 12) as usize & 63] as char);
        out.push(if c.len() > 1 { A[(n >> 6) as usize & 63] as char } else { '=' });
        out.push(if c.len() > 2 { A[n as usize & 63] as char } else { '=' });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_and_escaping() {
        assert_eq!(base64(b"Man"), "TWFu");
        assert_eq!(base64(b"Ma"), "TWE=");
        assert_eq!(base64(b"M"), "TQ==");
        assert_eq!(script_safe("\"</script><img>\""), "\"\\u003c/script\\u003e\\u003cimg\\u003e\"");
        assert_eq!(esc_html("<a href=\"x\">&"), "&lt;a href=&quot;x&quot;&gt;&amp;");
    }

    /// The page carries the engine (a WebAssembly module) and the job; the empty page lists the
    /// controllers and no programme.
    #[test]
    fn the_page_carries_its_engine() {
        assert_eq!(engine_missing(), None, "build with the wasm32-unknown-unknown target installed");
        assert_eq!(&ENGINE[..4], b"\0asm");
        let mut page = Vec::new();
        write(None, &mut page).unwrap();
        let page = String::from_utf8(page).unwrap();
        assert!(page.contains(&base64(&ENGINE[..3000])[..4000]));
        let job = &page[page.find("id=\"ncsight-job\">").unwrap()..];
        assert!(job.contains("[\"gsk980tdi\",") && !job[..job.find("</script>").unwrap()].contains("\"text\""));
    }
}
