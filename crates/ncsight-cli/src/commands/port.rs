//! `port`: the programme rewritten for another controller and verified by running both.

use crate::*;

/// Exit status of a port whose motion differs on the target (docs/reference/interface.md).
pub(crate) const EXIT_PORT_DIFFERS: i32 = 4;

/// `ncsight port`: the programme in the target's words, verified by running both.
pub(crate) fn port(
    file: &str,
    m: &MachineArgs,
    (to, to_setup): (&str, Option<&str>),
    output: Option<&str>,
    format: &str,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<i32, Failure> {
    if format != "text" && format != "json" {
        return Err(usage(format!("--format {format}: choose text or json")));
    }
    let mut head = Head::of(file)?;
    let from_name = machine_for(m, head.named(shown(file)), true, err)?;
    let from = m.job(&from_name)?;
    // The target runs as the source is asked to (switches, variables, the main programme,
    // where called programmes are), on its own machine with its own setup.
    let mut target = ncsight_io::Job {
        switches: from.switches,
        vars: from.vars.clone(),
        main: from.main.clone(),
        call_args: from.call_args.clone(),
        subprogram_dirs: from.subprogram_dirs.clone(),
        skip_missing_subprograms: from.skip_missing_subprograms,
        max_blocks: from.max_blocks,
        ..ncsight_io::Job::on(to)
    };
    let to_profile = target.profile()?;
    if from.profile()?.is_lathe() != to_profile.is_lathe() {
        let kind = if from.profile()?.is_lathe() { "lathe" } else { "machining centre" };
        return Err(usage(format!("--to {to}: a {kind} programme ports to a {kind} only")));
    }
    if let Some(path) = to_setup {
        target.read_setup(path)?;
    }
    // Standard input was read for its first line already: the rest comes through the head.
    let source = match head.input(file)? {
        feed::Input::Stream(mut r) => {
            let mut v = Vec::new();
            r.read_to_end(&mut v)?;
            v
        }
        _ => read_whole(file)?,
    };
    let decoding = m.decoding()?;
    let text = editor_text(&source, &decoding);
    let result = match ncsight_io::port::port(&from, &target, text.as_bytes()) {
        Ok(p) => p,
        Err(ncsight_io::port::PortError::Usage(e)) => return Err(usage(e)),
        Err(ncsight_io::port::PortError::SourceAlarm(line, msg)) => {
            let _ = writeln!(err, "ncsight: {}:{line}: the programme alarms on {from_name}: {msg}; nothing is written", shown(file));
            return Ok(EXIT_ALARM);
        }
    };
    // The programme names its controller on its first line (`(ncsight: TO)`, port.rs).
    let programme = result.text.clone();
    let status = if result.exact() { EXIT_OK } else { EXIT_PORT_DIFFERS };
    let bytes = as_opened(&programme, &source, &decoding);
    match output {
        Some(path) => {
            if m.read_files(file).iter().any(|f| same_file::is_same_file(f, path).unwrap_or(false)) {
                return Err(usage(format!("-o {path}: that is the programme being read; choose another file")));
            }
            std::fs::write(path, &bytes).map_err(|e| usage(format!("cannot write {path}: {e}")))?;
        }
        None if format == "text" => out.write_all(&bytes)?,
        None => {}
    }
    if format == "json" {
        let diffs: Vec<String> = result
            .differences
            .iter()
            .map(|d| format!("{{\"line\":{},\"what\":{},\"size\":{}}}", d.line, ncsight_io::format::jsonl::json_str(&d.what), d.size))
            .collect();
        let rewrites: Vec<String> =
            result.rewritten.iter().map(|(l, why)| format!("{{\"line\":{l},\"why\":{}}}", ncsight_io::format::jsonl::json_str(why))).collect();
        let mut text_field = if output.is_none() { format!(",\"text\":{}", ncsight_io::format::jsonl::json_str(&programme)) } else { String::new() };
        let params: Vec<String> = result
            .parameters
            .iter()
            .map(|(k, v, m)| {
                format!("{{\"key\":{},\"value\":{v},\"meaning\":{}}}", ncsight_io::format::jsonl::json_str(k), ncsight_io::format::jsonl::json_str(m))
            })
            .collect();
        text_field.push_str(&format!(",\"parameters\":[{}]", params.join(",")));
        writeln!(
            out,
            "{{\"from\":{},\"to\":{},\"exact\":{},\"rewritten\":[{}],\"differences\":[{}]{text_field}}}",
            ncsight_io::format::jsonl::json_str(&from_name),
            ncsight_io::format::jsonl::json_str(to_profile.name),
            result.exact(),
            rewrites.join(","),
            diffs.join(",")
        )?;
    } else {
        for (l, why) in &result.rewritten {
            let _ = writeln!(err, "ncsight: line {l} written as its moves: {why}");
        }
        for d in &result.differences {
            let _ = writeln!(err, "ncsight: difference at line {}: {} ({})", d.line, d.what, d.size);
        }
        for (k, v, m) in &result.parameters {
            let _ = writeln!(err, "ncsight: {} parameter {k} = {v} as assumed (its power-on value): {m}", to_profile.name);
        }
        let _ = writeln!(err, "ncsight: {} -> {}: {}", from_name, to_profile.name, if result.exact() { "the same motion" } else { "approximate" });
    }
    Ok(status)
}

/// A text written the way `source` was: GBK (the encoding its lines that are not UTF-8 were read
/// in) when it was not UTF-8, as GSK controllers and Chinese editors save; CR LF line ends and a
/// byte-order mark where it had them.
pub(crate) fn as_opened(text: &str, source: &[u8], decoding: &diag::Decoding) -> Vec<u8> {
    let crlf = source.windows(2).any(|w| w == b"\r\n");
    let text = if crlf { text.replace("\r\n", "\n").replace('\n', "\r\n") } else { text.to_string() };
    let mut out = Vec::with_capacity(text.len() + 3);
    if source.starts_with(&[0xEF, 0xBB, 0xBF]) {
        out.extend_from_slice(&[0xEF, 0xBB, 0xBF]);
    }
    match std::str::from_utf8(source) {
        Ok(_) => out.extend_from_slice(text.as_bytes()),
        Err(_) => {
            let enc = encoding_rs::Encoding::for_label(decoding.label().as_bytes()).unwrap_or(encoding_rs::GB18030);
            out.extend_from_slice(&enc.encode(&text).0);
        }
    }
    out
}

/// A programme file (or standard input) read whole.
pub(crate) fn read_whole(file: &str) -> Result<Vec<u8>, Failure> {
    if file == "-" {
        let mut v = Vec::new();
        io::stdin().read_to_end(&mut v)?;
        return Ok(v);
    }
    std::fs::read(file).map_err(|e| usage(format!("cannot read {file}: {e}")))
}
