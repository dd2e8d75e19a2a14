//! The cut stock for the page's 3D view: a run of the programme cut into the stock at a display
//! resolution, packed so the page reads it into typed arrays. Cut up to a time, it is the stock
//! as the programme plays.
//!
//! Layout (little-endian):
//!
//! ```text
//! "NCST"  u32 J  J bytes of JSON (the header)  zero bytes up to a multiple of 4
//! lathe:  outer f32 x (ntheta x nz), inner f32 x (ntheta x nz): radii, one row of nz (from the
//!         chuck's end toward the face) per angle
//! mill:   top f32 x (nx x ny): the material's top, one row of nx (along X) per Y
//! ```
//!
//! The header says `kind` (`lathe` or `mill`), the grid (`nz`, `ntheta`, `z0_mm`, `dz_mm`; or
//! `nx`, `ny`, `x0_mm`, `y0_mm`, `cell_mm`), the stock (`diameter_mm`, `bore_mm`,
//! `front_z_mm`, `length_mm`, `guessed`; or `top_mm`, `bottom_mm`), `until_s`, `cut` (the run
//! was longer than [`super::scene::MAX_SCENE_RECORDS`] records: the stock is cut by the first
//! ones) and the `findings` of the simulation (as `simulate --format json` writes them).

use super::jsonl::json_str;
use super::num;
use crate::job::{Job, JobError};
use ncsight::stock::measure::{simulate, MillCut, SimOptions};
use ncsight::stock::survey::MillSurvey;
use ncsight::stock::Finding;
use ncsight::{Event, Mode, Record};
use std::fmt::Write as _;

/// Cells along Z the lathe view has at most (it is drawn, not measured).
pub const VIEW_NZ: f64 = 1500.0;
/// Angles around the lathe view has (3 degrees apart).
pub const VIEW_NTHETA: usize = 120;
/// Cells across the mill view's longer side.
pub const VIEW_ACROSS: f64 = 400.0;

/// A finding as a JSON object: kind, line, message and, where known, x (a diameter on a lathe),
/// y, z, spindle_deg, t and the tool.
pub fn finding_json(f: &Finding) -> String {
    let mut s = format!("{{\"kind\":\"{}\",\"line\":{},\"message\":{}", f.kind, f.line, json_str(&f.message));
    if let Some(p) = &f.at {
        let _ = write!(s, ",\"x\":{},\"y\":{},\"z\":{}", num(p.x_mm, 4), num(p.y_mm, 4), num(p.z_mm, 4));
        if let Some(a) = p.spindle_deg {
            let _ = write!(s, ",\"spindle_deg\":{}", num(a, 3));
        }
        let _ = write!(s, ",\"t\":{}", num(p.t_s, 3));
    }
    if let Some(t) = f.tool {
        let _ = write!(s, ",\"tool\":{t}");
    }
    s.push('}');
    s
}

/// Run `text` as `job` says and cut its stock (the job's setup, with `stock` as `--stock` takes
/// it when not empty), the records that have ended by `until_s` (all when None), on the view's
/// grid or one of `resolution_mm` cells.
pub fn stock_view(
    job: &Job,
    text: &[u8],
    library: Vec<(String, &[u8])>,
    stock: &str,
    until_s: Option<f64>,
    resolution_mm: Option<f64>,
) -> Result<Vec<u8>, JobError> {
    let profile = job.profile()?;
    let mut setup = job.setup.clone().unwrap_or_default();
    if !stock.trim().is_empty() {
        setup.set_stock_text(stock.trim(), profile.is_lathe()).map_err(|e| JobError::Usage(e.to_string()))?;
    }
    let (program, _) = job.program(Mode::Run)?;
    let mut records: Vec<Record> = Vec::new();
    let mut cut = false;
    for e in ncsight::events_with_library(program, text, library) {
        if let Event::Record(r) = e {
            if records.len() >= super::scene::MAX_SCENE_RECORDS {
                cut = true;
                break;
            }
            records.push(r);
        }
    }
    let until = until_s.map_or("null".to_string(), |t| num(t, 4));
    let (head, arrays) =
        if profile.is_lathe() { lathe_view(&records, &setup, until_s, resolution_mm)? } else { mill_view(&records, &setup, until_s, resolution_mm)? };
    let head = format!("{{{head},\"until_s\":{until},\"cut\":{cut}}}");
    let mut out = Vec::with_capacity(8 + head.len() + 4 * arrays.iter().map(|a| a.len()).sum::<usize>());
    out.extend_from_slice(b"NCST");
    out.extend_from_slice(&(head.len() as u32).to_le_bytes());
    out.extend_from_slice(head.as_bytes());
    out.resize(out.len().div_ceil(4) * 4, 0);
    for a in arrays {
        for v in a {
            out.extend_from_slice(&v.to_le_bytes());
        }
    }
    Ok(out)
}

fn findings_json(findings: &[Finding]) -> String {
    findings.iter().map(finding_json).collect::<Vec<_>>().join(",")
}

/// The lathe's header fields and its outer and inner radii, on a grid of at most [`VIEW_NZ`]
/// cells along the bar (at least 0.01 mm apart) and [`VIEW_NTHETA`] around.
fn lathe_view(
    records: &[Record],
    setup: &ncsight::setup::Setup,
    until_s: Option<f64>,
    resolution_mm: Option<f64>,
) -> Result<(String, Vec<Vec<f32>>), JobError> {
    let length_mm = match setup.stock {
        Some(b) => b.length_mm,
        // The programme's extent along Z, which a guessed stock spans (and 5 mm more).
        None => records.iter().filter_map(|r| r.op.end_point()).map(|p| p.z).fold(0.0f64, |a, z| a.max(-z)) + 5.0,
    };
    let dz = resolution_mm.unwrap_or((length_mm / VIEW_NZ).clamp(0.01, 5.0));
    let opts = SimOptions { dz_mm: Some(dz), dtheta_deg: Some(360.0 / VIEW_NTHETA as f64), until_s, ..SimOptions::default() };
    let sim = simulate(records, setup, &opts).map_err(JobError::Usage)?;
    let (g, b) = (sim.stock.grid, sim.stock.bar);
    let head = format!(
        "\"kind\":\"lathe\",\"nz\":{},\"ntheta\":{},\"z0_mm\":{},\"dz_mm\":{},\"diameter_mm\":{},\"bore_mm\":{},\"front_z_mm\":{},\"length_mm\":{},\"guessed\":{},\"findings\":[{}]",
        g.nz,
        g.ntheta,
        num(g.z0_mm, 6),
        num(g.dz_mm, 6),
        num(b.diameter_mm, 4),
        num(b.bore_mm, 4),
        num(b.front_z_mm, 4),
        num(b.length_mm, 4),
        sim.measurement.stock_guessed.is_some(),
        findings_json(&sim.measurement.findings)
    );
    Ok((head, vec![sim.stock.outer, sim.stock.inner]))
}

/// The mill's header fields and its tops, [`VIEW_ACROSS`] cells across the longer side (at
/// least 0.1 mm).
fn mill_view(records: &[Record], setup: &ncsight::setup::Setup, until_s: Option<f64>, resolution_mm: Option<f64>) -> Result<(String, Vec<Vec<f32>>), JobError> {
    // One survey serves the view's cell size and the cut.
    let mut survey = MillSurvey::default();
    records.iter().for_each(|r| survey.add(r));
    // The block's longer side, for the cell size: the setup's, or the cutting moves' extent
    // and 10 mm either side.
    let across = match setup.block {
        Some(b) => (b.max_mm[0] - b.min_mm[0]).max(b.max_mm[1] - b.min_mm[1]),
        None => (0..2).map(|k| survey.cut_max[k] - survey.cut_min[k]).fold(0.0, f64::max) + 20.0,
    };
    let cell = resolution_mm.unwrap_or((across / VIEW_ACROSS).max(0.1));
    let mut cut = MillCut::new(&survey, setup, Some(cell), until_s).map_err(JobError::Usage)?;
    records.iter().for_each(|r| cut.add(r));
    let sim = cut.finish();
    let s = &sim.stock;
    let head = format!(
        "\"kind\":\"mill\",\"nx\":{},\"ny\":{},\"x0_mm\":{},\"y0_mm\":{},\"cell_mm\":{},\"top_mm\":{},\"bottom_mm\":{},\"removed_mm3\":{},\"findings\":[{}]",
        s.nx,
        s.ny,
        num(s.block.min_mm[0], 4),
        num(s.block.min_mm[1], 4),
        num(s.cell_mm, 6),
        num(s.block.max_mm[2], 4),
        num(s.block.min_mm[2], 4),
        num(s.removed_mm3(), 1),
        findings_json(&sim.findings)
    );
    Ok((head, vec![sim.stock.top]))
}
