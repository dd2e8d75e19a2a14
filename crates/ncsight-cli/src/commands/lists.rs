//! `machines` and `explain`: the profiles, their codes and parameters, and the alarms explained.

use crate::*;

/// One code of `machines NAME`: the code, its status, what it does, where that comes from.
pub(crate) fn code_line(out: &mut dyn Write, code: &str, status: ncsight::profile::CodeStatus, meaning: &str, source: &str) -> std::io::Result<()> {
    use ncsight::profile::CodeStatus;
    let (state, why) = match status {
        CodeStatus::Simulated => ("simulated", String::new()),
        CodeStatus::Assumed(a) => ("assumed", format!(" ({a})")),
        CodeStatus::NotYet => ("not yet", String::new()),
    };
    writeln!(out, "  {code:<7} {state:<10} {meaning}{why} [{source}]")
}

/// `ncsight explain CODE [--lang en|zh]`, `ncsight explain --list`.
pub(crate) fn explain(code: Option<&str>, lang: Option<&str>, list: bool, out: &mut dyn Write) -> Result<i32, Failure> {
    use ncsight::explain::Lang;
    let lang = match lang {
        Some(l) if l.eq_ignore_ascii_case("zh") || l.to_ascii_lowercase().starts_with("zh") => Lang::Zh,
        Some(l) if l.eq_ignore_ascii_case("en") => Lang::En,
        Some(l) => return Err(usage(format!("--lang {l}: choose en or zh"))),
        None => {
            // The locale, as a terminal gives it.
            let zh = ["LC_ALL", "LC_MESSAGES", "LANG"]
                .iter()
                .find_map(|k| std::env::var(k).ok().filter(|v| !v.is_empty()))
                .is_some_and(|v| v.to_ascii_lowercase().starts_with("zh"));
            if zh {
                Lang::Zh
            } else {
                Lang::En
            }
        }
    };
    if list {
        for r in ncsight::Rule::ALL {
            writeln!(out, "{:<8} {:<7} {}", r.project_code(), r.fanuc_code().unwrap_or("-"), r.title())?;
        }
        return Ok(EXIT_OK);
    }
    let Some(code) = code else {
        return Err(usage("ncsight explain CODE (NCS-E53, PS0063), or --list"));
    };
    match ncsight::explain::explain(code) {
        Some((rule, e)) => {
            out.write_all(ncsight::explain::render(rule, &e, lang).as_bytes())?;
            Ok(EXIT_OK)
        }
        None => Err(usage(format!("{code}: no such code (ncsight explain --list lists them)"))),
    }
}

pub(crate) fn machines(name: Option<&str>, out: &mut dyn Write) -> Result<i32, Failure> {
    match name {
        None => {
            for p in profile::all() {
                writeln!(out, "{:<12} {}", p.name, p.title)?;
            }
        }
        Some(n) => {
            let p = profile::by_name(n).ok_or_else(|| usage(format!("unknown machine '{n}': choose one of {}", names())))?;
            writeln!(out, "{} - {}\n", p.name, p.title)?;
            writeln!(out, "{}\n", p.summary)?;
            // The key column as wide as the longest key (setting names are long).
            let w = p.all_params().map(|d| d.key.to_string().len()).max().unwrap_or(0).max(9);
            writeln!(out, "{:<w$} {:>10} {:<11} {:<16} meaning [source]", "parameter", "default", "unit", "range")?;
            for d in p.all_params() {
                writeln!(
                    out,
                    "{:<w$} {:>10} {:<11} {:<16} {} [{}]",
                    d.key.to_string(),
                    format::num(d.default, 4),
                    d.unit,
                    format!("{}..{}", format::num(d.min, 4), format::num(d.max, 4)),
                    d.meaning,
                    d.source
                )?;
            }
            writeln!(
                out,
                "\nG codes (status: simulated; assumed = runs with a warning that names the assumption; not yet = alarm NCS-E38, not simulated yet):"
            )?;
            for t in p.g_codes {
                for g in t.codes {
                    code_line(out, g.name, p.code_status(g), g.meaning, t.source)?;
                }
            }
            writeln!(out, "\nM codes:")?;
            for t in p.m_codes {
                for mc in t.codes {
                    code_line(out, &format!("M{:02}", mc.code), mc.function.status(), mc.meaning, t.source)?;
                }
            }
        }
    }
    Ok(EXIT_OK)
}
