//! `ncsight simulate`: run the programme, cut the stock, print the measurement and findings,
//! and draw the unrolled surface as a PNG.

use crate::format::{jsonl::json_str, num};
use ncsight::stock::measure::{Measurement, SimOptions, Simulation};
use ncsight::stock::{Finding, ToolKind};
use std::io::{self, Write};

fn opt(v: Option<f64>, decimals: usize) -> String {
    v.map(|v| num(v, decimals)).unwrap_or_else(|| "null".into())
}

use crate::format::stock::finding_json;

/// A finding for a person: kind, line, where and when, what.
fn finding_text(f: &Finding, lathe: bool) -> String {
    let mut at = String::new();
    if let Some(p) = &f.at {
        if lathe {
            at = format!(" at X{} Z{}", num(p.x_mm, 3), num(p.z_mm, 3));
        } else {
            at = format!(" at X{} Y{} Z{}", num(p.x_mm, 3), num(p.y_mm, 3), num(p.z_mm, 3));
        }
        if let Some(a) = p.spindle_deg {
            at.push_str(&format!(", spindle {} deg", num(a, 3)));
        }
        at.push_str(&format!(", t={} s", num(p.t_s, 3)));
    }
    format!("finding {:<14} line {}{at}: {}\n", f.kind, f.line, f.message)
}

/// The tools assumed where the setup has none, as the output says them.
pub fn assumed_tools(m: &Measurement) -> Vec<String> {
    m.assumed_tools
        .iter()
        .map(|(n, t)| match t.kind {
            ToolKind::Thread if t.internal => format!("T{n}: internal threading insert, {} degrees, sharp", num(t.included_angle_deg, 1)),
            ToolKind::Thread => format!("T{n}: threading insert, {} degrees, sharp", num(t.included_angle_deg, 1)),
            ToolKind::Drill => format!("T{n}: drill {} mm on the spindle axis, {}-degree point", num(t.diameter_mm, 3), num(t.point_angle_deg, 1)),
            ToolKind::Turning => format!(
                "T{n}: turning insert, {} degrees, nose radius {} mm (each move cuts the side of the material it is nearer to)",
                num(t.included_angle_deg, 1),
                num(t.tip_radius_mm, 3)
            ),
            ToolKind::Boring => format!("T{n}: boring bar, {}-degree insert, nose radius {} mm", num(t.included_angle_deg, 1), num(t.tip_radius_mm, 3)),
            // Never assumed (measure.rs assumes the kinds above); named for completeness.
            other => format!("T{n}: {other:?}").to_lowercase(),
        })
        .collect()
}

/// The measurement as one JSON object.
pub fn json(m: &Measurement) -> String {
    let findings: Vec<String> = m.findings.iter().map(finding_json).collect();
    let flanks = m.flank_angles_deg.map(|(a, b)| format!("[{},{}]", num(a, 2), num(b, 2))).unwrap_or_else(|| "null".into());
    format!(
        "{{\"assumed_tools\":[{}],\"stock_diameter_mm\":{},\"stock_guessed\":{},\"major_diameter_mm\":{},\"minor_diameter_mm\":{},\"depth_mm\":{},\"pitch_mm\":{},\"lead_mm\":{},\"hand\":{},\"starts\":{},\"start_spacing_deg\":{},\"flank_angles_deg\":{flanks},\"full_depth_length_mm\":{},\"runout_length_mm\":{},\"grid\":{{\"dz_mm\":{},\"dtheta_deg\":{},\"cell_updates\":{}}},\"profile\":[{}],\"findings\":[{}]}}\n",
        assumed_tools(m).iter().map(|t| json_str(t)).collect::<Vec<_>>().join(","),
        num(m.stock_diameter_mm, 4),
        m.stock_guessed.map(|b| format!("{{\"diameter_mm\":{},\"length_mm\":{},\"front_z_mm\":{},\"bore_mm\":{}}}", num(b.diameter_mm, 4), num(b.length_mm, 4), num(b.front_z_mm, 4), num(b.bore_mm, 4))).unwrap_or_else(|| "null".into()),
        opt(m.major_diameter_mm, 4),
        opt(m.minor_diameter_mm, 4),
        opt(m.depth_mm, 4),
        opt(m.pitch_mm, 4),
        opt(m.lead_mm, 4),
        m.hand.map(|h| format!("\"{h}\"")).unwrap_or_else(|| "null".into()),
        m.starts.map(|s| s.to_string()).unwrap_or_else(|| "null".into()),
        opt(m.start_spacing_deg, 3),
        opt(m.full_depth_length_mm, 3),
        opt(m.runout_length_mm, 3),
        num(m.dz_mm, 6),
        num(m.dtheta_deg, 6),
        m.cell_updates,
        m.profile
            .iter()
            .map(|r| format!(
                "{{\"z_from_mm\":{},\"z_to_mm\":{},\"outer_diameter_mm\":{},\"inner_diameter_mm\":{}}}",
                num(r.z_from_mm, 4),
                num(r.z_to_mm, 4),
                num(r.outer_diameter_mm, 3),
                num(r.inner_diameter_mm, 3)
            ))
            .collect::<Vec<_>>()
            .join(","),
        findings.join(",")
    )
}

/// A drilling simulation as one JSON object.
pub fn mill_json(sim: &ncsight::stock::measure::MillSimulation) -> String {
    let holes: Vec<String> = sim
        .holes
        .iter()
        .map(|h| format!("{{\"x\":{},\"y\":{},\"depth_mm\":{},\"diameter_mm\":{}}}", num(h.x, 3), num(h.y, 3), num(h.depth_mm, 3), num(h.diameter_mm, 3)))
        .collect();
    let findings: Vec<String> = sim.findings.iter().map(finding_json).collect();
    let floors: Vec<String> = sim.stock.floors().iter().map(|(z, a)| format!("{{\"z_mm\":{},\"area_mm2\":{}}}", num(*z, 3), num(*a, 2))).collect();
    let assumed: Vec<String> = mill_assumed(sim).iter().map(|t| json_str(t)).collect();
    let guessed = match sim.block_guessed {
        Some(b) => format!("{{\"min_mm\":[{}],\"max_mm\":[{}]}}", b.min_mm.map(|v| num(v, 4)).join(","), b.max_mm.map(|v| num(v, 4)).join(",")),
        None => "null".into(),
    };
    format!(
        "{{\"assumed_tools\":[{}],\"block_guessed\":{guessed},\"holes\":[{}],\"floors\":[{}],\"removed_mm3\":{},\"grid\":{{\"cell_mm\":{}}},\"findings\":[{}]}}\n",
        assumed.join(","),
        holes.join(","),
        floors.join(","),
        num(sim.stock.removed_mm3(), 1),
        num(sim.stock.cell_mm, 4),
        findings.join(",")
    )
}

/// A machining centre's assumed tools, for a person.
fn mill_assumed(sim: &ncsight::stock::measure::MillSimulation) -> Vec<String> {
    sim.assumed_tools
        .iter()
        .map(|(n, t)| match t.kind {
            ToolKind::Mill => format!("T{n}: flat end mill {} mm", num(t.diameter_mm, 3)),
            _ => format!("T{n}: drill {} mm, {}-degree point", num(t.diameter_mm, 3), num(t.point_angle_deg, 1)),
        })
        .collect()
}

/// A drilling simulation for a person.
pub fn mill_text(sim: &ncsight::stock::measure::MillSimulation) -> String {
    let mut s = String::new();
    for t in mill_assumed(sim) {
        s.push_str(&format!("tool assumed: {t}\n"));
    }
    if let Some(b) = sim.block_guessed {
        let p = |v: [f64; 3]| v.map(|c| num(c, 3)).join(", ");
        s.push_str(&format!("block guessed: [{}] to [{}] mm (from the programme's cuts: give --stock XxYxZ or [block])\n", p(b.min_mm), p(b.max_mm)));
    }
    s.push_str(&format!("{} hole(s) on a {} mm grid\n", sim.holes.len(), num(sim.stock.cell_mm, 4)));
    for h in &sim.holes {
        s.push_str(&format!("hole at X{} Y{}: depth {} mm, diameter {} mm\n", num(h.x, 3), num(h.y, 3), num(h.depth_mm, 3), num(h.diameter_mm, 3)));
    }
    for (z, area) in sim.stock.floors().iter().take(20) {
        s.push_str(&format!("floor at Z{}: {} mm2\n", num(*z, 3), num(*area, 1)));
    }
    s.push_str(&format!("removed {} mm3\n", num(sim.stock.removed_mm3(), 1)));
    for f in &sim.findings {
        s.push_str(&finding_text(f, false));
    }
    s
}

/// The measurement for a person.
pub fn text(m: &Measurement) -> String {
    let mut s = String::new();
    // What was not simulated comes first: the measurement below does not include it.
    for f in m.findings.iter().filter(|f| !f.is_problem()) {
        s.push_str(&finding_text(f, true));
    }
    for t in assumed_tools(m) {
        s.push_str(&format!("{:<22} {t}\n", "tool assumed"));
    }
    let line = |s: &mut String, what: &str, v: Option<f64>, unit: &str| {
        s.push_str(&format!("{what:<22} {}\n", v.map(|v| format!("{} {unit}", num(v, 4))).unwrap_or_else(|| "-".into())));
    };
    line(&mut s, "stock diameter", Some(m.stock_diameter_mm), "mm");
    if let Some(b) = m.stock_guessed {
        s.push_str(&format!(
            "{:<22} {} x {} mm from Z{} (guessed from the programme's cuts: give --stock DIAxLEN)\n",
            "stock guessed",
            num(b.diameter_mm, 3),
            num(b.length_mm, 3),
            num(b.front_z_mm, 3)
        ));
    }
    line(&mut s, "major diameter", m.major_diameter_mm, "mm");
    line(&mut s, "minor diameter", m.minor_diameter_mm, "mm");
    line(&mut s, "thread depth", m.depth_mm, "mm");
    line(&mut s, "pitch", m.pitch_mm, "mm");
    line(&mut s, "lead", m.lead_mm, "mm");
    s.push_str(&format!("{:<22} {}\n", "hand", m.hand.unwrap_or("-")));
    s.push_str(&format!(
        "{:<22} {}\n",
        "starts",
        m.starts.map(|v| format!("{v}, {} deg apart", num(m.start_spacing_deg.unwrap_or(0.0), 2))).unwrap_or_else(|| "-".into())
    ));
    s.push_str(&format!(
        "{:<22} {}\n",
        "flank angles",
        m.flank_angles_deg.map(|(a, b)| format!("{} + {} deg", num(a, 2), num(b, 2))).unwrap_or_else(|| "-".into())
    ));
    line(&mut s, "full-depth length", m.full_depth_length_mm, "mm");
    line(&mut s, "run-out length", m.runout_length_mm, "mm");
    profile_text(&mut s, &m.profile);
    s.push_str(&format!("{:<22} {} mm x {} deg, {} cell updates\n", "grid", num(m.dz_mm, 5), num(m.dtheta_deg, 4), m.cell_updates));
    if !m.findings.iter().any(|f| f.is_problem()) {
        s.push_str("findings               none\n");
    }
    for f in m.findings.iter().filter(|f| f.is_problem()) {
        s.push_str(&finding_text(f, true));
    }
    s
}

/// The unrolled surface: z across, theta down, darker is deeper.
pub fn image(sim: &Simulation, w: &mut dyn Write) -> io::Result<()> {
    let g = sim.stock.grid;
    let step = g.nz.div_ceil(2000).max(1);
    let width = g.nz.div_ceil(step);
    let (lo, hi) = sim.stock.measured().iter().fold((f32::MAX, f32::MIN), |(a, b), v| (a.min(*v), b.max(*v)));
    let span = (hi - lo).max(1e-6);
    let mut data = Vec::with_capacity(width * g.ntheta);
    for j in 0..g.ntheta {
        let row = sim.stock.row(j);
        for i in (0..g.nz).step_by(step) {
            data.push((((row[i] - lo) / span) * 255.0) as u8);
        }
    }
    let mut enc = png::Encoder::new(w, width as u32, g.ntheta as u32);
    enc.set_color(png::ColorType::Grayscale);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header().map_err(io::Error::other)?;
    writer.write_image_data(&data).map_err(io::Error::other)?;
    Ok(())
}

/// Resolution `DZ,DTHETA` (mm, degrees).
pub fn resolution(text: &str) -> Option<(f64, f64)> {
    let (a, b) = text.split_once(',')?;
    let (a, b): (f64, f64) = (a.trim().parse().ok()?, b.trim().parse().ok()?);
    (a > 0.0 && b > 0.0 && a.is_finite() && b.is_finite()).then_some((a, b))
}

/// Options from the command line.
pub fn options(res: Option<&str>, expect: Option<&str>) -> Result<SimOptions, String> {
    let (dz, dt) = match res {
        // One number: the cell (a machining centre's grid, or a lathe's DZ with the default angle).
        Some(r) if !r.contains(',') => match r.trim().parse::<f64>() {
            Ok(v) if v.is_finite() && v > 0.0 => (Some(v), None),
            _ => return Err(format!("--resolution {r}: write MM (a mill's cell) or DZ,DTHETA in mm and degrees, e.g. 0.01,0.5")),
        },
        Some(r) => resolution(r)
            .map(|(a, b)| (Some(a), Some(b)))
            .ok_or_else(|| format!("--resolution {r}: write MM (a mill's cell) or DZ,DTHETA in mm and degrees, e.g. 0.01,0.5"))?,
        None => (None, None),
    };
    // `bore=D` and `od=D` are sizes; the rest names the thread (`M24x2`, `major=..,minor=..`).
    let (mut bore, mut od, mut thread) = (None, None, Vec::new());
    for piece in expect.unwrap_or("").split(',').map(str::trim).filter(|p| !p.is_empty()) {
        let size = |v: &str| v.trim().parse::<f64>().ok().filter(|d| d.is_finite() && *d > 0.0).ok_or_else(|| format!("--expect {piece}: a diameter in mm"));
        match piece.split_once('=') {
            Some(("bore", v)) => bore = Some(size(v)?),
            Some(("od", v)) => od = Some(size(v)?),
            _ => thread.push(piece),
        }
    }
    let expect = if thread.is_empty() { None } else { Some(ncsight::stock::standard::parse(&thread.join(","))?) };
    Ok(SimOptions { dz_mm: dz, dtheta_deg: dt, expect, expect_bore_mm: bore, expect_od_mm: od, until_s: None })
}

/// The profile for a person: each section of 0.2 mm or longer on a line, the short rows between
/// them (a radius, a chamfer, a drill's point) as one transition from where they start to where
/// they end; at most 40 lines (`--format json` has every row).
fn profile_text(s: &mut String, rows: &[ncsight::stock::lathe::ProfileRow]) {
    const SECTION_MM: f64 = 0.2;
    const SHOWN: usize = 40;
    let size = |r: &ncsight::stock::lathe::ProfileRow| match (r.outer_diameter_mm > 0.0, r.inner_diameter_mm > 0.0) {
        (false, _) => "no material".to_string(),
        (true, false) => format!("diameter {}", num(r.outer_diameter_mm, 3)),
        (true, true) => format!("diameter {}, bore {}", num(r.outer_diameter_mm, 3), num(r.inner_diameter_mm, 3)),
    };
    let mut lines: Vec<String> = Vec::new();
    let mut k = 0;
    while k < rows.len() {
        let r = &rows[k];
        if r.length_mm() >= SECTION_MM {
            lines.push(format!("Z{} to Z{}: {}", num(r.z_from_mm, 3), num(r.z_to_mm, 3), size(r)));
            k += 1;
            continue;
        }
        let first = k;
        while k < rows.len() && rows[k].length_mm() < SECTION_MM {
            k += 1;
        }
        let last = &rows[k - 1];
        lines.push(format!("Z{} to Z{}: from {} to {}", num(rows[first].z_from_mm, 3), num(last.z_to_mm, 3), size(&rows[first]), size(last)));
    }
    for l in lines.iter().take(SHOWN) {
        s.push_str(&format!("{:<22} {l}\n", "profile"));
    }
    if lines.len() > SHOWN {
        s.push_str(&format!("{:<22} {} more (--format json lists every row)\n", "profile", lines.len() - SHOWN));
    }
}

/// A mesh as binary STL: an 80-byte header, the count, then each triangle's normal and corners
/// (f32, little-endian) and a zero attribute. `mesh` hands the triangles over and returns their
/// count; it is run twice, once to count (nothing is held).
pub fn stl(w: &mut dyn Write, mesh: &dyn Fn(&mut dyn FnMut(ncsight::stock::mesh::Triangle)) -> u32) -> io::Result<()> {
    let n = mesh(&mut |_| {});
    let mut header = [b' '; 80];
    let title = b"ncsight simulate: the cut stock, mm, programme coordinates";
    header[..title.len()].copy_from_slice(title);
    w.write_all(&header)?;
    w.write_all(&n.to_le_bytes())?;
    let mut failed = Ok(());
    let mut buf = [0u8; 50];
    mesh(&mut |(normal, corners)| {
        if failed.is_err() {
            return;
        }
        for (k, p) in std::iter::once(normal).chain(corners).enumerate() {
            for (c, v) in [p.x, p.y, p.z].into_iter().enumerate() {
                let at = 12 * k + 4 * c;
                buf[at..at + 4].copy_from_slice(&(v as f32).to_le_bytes());
            }
        }
        failed = w.write_all(&buf);
    });
    failed
}

/// The lathe part's axial section ([`ncsight::stock::section`]) as an SVG drawing: millimetres,
/// Z across (the chuck's end at the left), the diameter up, the material hatched grey with a
/// black outline, the spindle axis dash-dotted, the stock's size in the title.
pub fn section_svg(w: &mut dyn Write, stock: &ncsight::stock::lathe::LatheStock) -> io::Result<()> {
    let outlines = ncsight::stock::section::outlines(stock);
    let (b, m) = (stock.bar, 2.0);
    let r = b.diameter_mm / 2.0;
    let (z0, z1) = (b.front_z_mm - b.length_mm - m, b.front_z_mm + m);
    let (w_mm, h_mm) = (z1 - z0, 2.0 * (r + m));
    writeln!(w, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>")?;
    writeln!(
        w,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}mm\" height=\"{}mm\" viewBox=\"{} {} {} {}\">",
        num(w_mm, 3),
        num(h_mm, 3),
        num(z0, 4),
        num(-(r + m), 4),
        num(w_mm, 4),
        num(h_mm, 4)
    )?;
    writeln!(w, "<title>ncsight simulate: section of the cut part, stock Ø{} x {} mm, mm</title>", num(b.diameter_mm, 3), num(b.length_mm, 3))?;
    // SVG's y runs down: a point above the axis is drawn at -y.
    for o in &outlines {
        let d: Vec<String> = o.iter().map(|(z, y)| format!("{},{}", num(*z, 4), num(-*y, 4))).collect();
        writeln!(w, "<polygon points=\"{}\" fill=\"#cfd8dc\" stroke=\"#000\" stroke-width=\"0.05\"/>", d.join(" "))?;
    }
    writeln!(
        w,
        "<line x1=\"{}\" y1=\"0\" x2=\"{}\" y2=\"0\" stroke=\"#455a64\" stroke-width=\"0.05\" stroke-dasharray=\"3 0.8 0.6 0.8\"/>",
        num(z0, 4),
        num(z1, 4)
    )?;
    writeln!(w, "</svg>")
}

/// The same section as a DXF drawing (ASCII, R12 entities every CAD program reads): the outlines
/// as LINEs on layer SECTION, the axis on layer AXIS; X the programme's Z, Y the radius, mm.
pub fn section_dxf(w: &mut dyn Write, stock: &ncsight::stock::lathe::LatheStock) -> io::Result<()> {
    let line = |w: &mut dyn Write, layer: &str, a: (f64, f64), b: (f64, f64)| -> io::Result<()> {
        write!(w, "0\nLINE\n8\n{layer}\n10\n{}\n20\n{}\n30\n0\n11\n{}\n21\n{}\n31\n0\n", num(a.0, 4), num(a.1, 4), num(b.0, 4), num(b.1, 4))
    };
    write!(w, "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n")?;
    for o in ncsight::stock::section::outlines(stock) {
        for k in 0..o.len() {
            line(w, "SECTION", o[k], o[(k + 1) % o.len()])?;
        }
    }
    let b = stock.bar;
    line(w, "AXIS", (b.front_z_mm - b.length_mm - 2.0, 0.0), (b.front_z_mm + 2.0, 0.0))?;
    write!(w, "0\nENDSEC\n0\nEOF\n")
}
