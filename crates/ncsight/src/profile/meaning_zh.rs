//! The Chinese (zh-CN) of every parameter's meaning: one table, `meaning_zh.toml`, from the
//! English text as the profiles write it (`ParamDef::meaning`) to its translation, in the words
//! of the Chinese GSK and FANUC manuals. Read once, from the text built into the library (no
//! I/O); a test holds it complete for every parameter of every profile and free of texts no
//! parameter uses any more.

use std::collections::HashMap;
use std::sync::OnceLock;

const TABLE: &str = include_str!("meaning_zh.toml");

fn table() -> Result<HashMap<String, String>, String> {
    toml::from_str(TABLE).map_err(|e| format!("the parameter meaning table: {e}"))
}

/// The Chinese of a parameter's meaning, by its English text (`ParamDef::meaning`, exactly);
/// `None` where the table has none (a test keeps every built-in parameter translated).
pub fn meaning_zh(meaning_en: &str) -> Option<&'static str> {
    static TRANSLATIONS: OnceLock<HashMap<String, String>> = OnceLock::new();
    // A table that does not parse gives no translation (its test names the mistake).
    let t = TRANSLATIONS.get_or_init(|| table().unwrap_or_default());
    t.get(meaning_en).map(String::as_str).filter(|s| !s.trim().is_empty())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::profile::{all, ParamDef, Profile};

    /// Every profile, with its G-code systems B and C where it has them.
    fn profiles() -> Vec<&'static Profile> {
        let mut out = Vec::new();
        for p in all() {
            out.push(p);
            if let Some(sys) = p.g_code_systems {
                out.extend([sys.profile_b, sys.profile_c]);
            }
        }
        out
    }

    fn defs() -> Vec<(&'static Profile, &'static ParamDef)> {
        profiles().into_iter().flat_map(|p| p.all_params().map(move |d| (p, d))).collect()
    }

    fn has_chinese(s: &str) -> bool {
        s.chars().any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c))
    }

    /// The runs of digits of a text (parameter numbers, codes, values).
    fn numbers(s: &str) -> Vec<&str> {
        s.split(|c: char| !c.is_ascii_digit()).filter(|w| !w.is_empty()).collect()
    }

    #[test]
    fn every_parameter_meaning_has_chinese() {
        table().unwrap();
        let mut missing = Vec::new();
        for (p, d) in defs() {
            match meaning_zh(d.meaning) {
                None => missing.push(format!("{} parameter {}: no Chinese for {:?}", p.name, d.key, d.meaning)),
                Some(zh) if !has_chinese(zh) => missing.push(format!("{} parameter {}: {zh:?} is not Chinese", p.name, d.key)),
                Some(zh) => {
                    let lost: Vec<&str> = numbers(d.meaning).into_iter().filter(|n| !zh.contains(n)).collect();
                    if !lost.is_empty() {
                        missing.push(format!("{} parameter {}: {zh:?} lacks {lost:?} of {:?}", p.name, d.key, d.meaning));
                    }
                }
            }
        }
        missing.dedup();
        assert!(missing.is_empty(), "{}", missing.join("\n"));
    }

    #[test]
    fn every_translated_meaning_is_used() {
        let used: Vec<&str> = defs().into_iter().map(|(_, d)| d.meaning).collect();
        let unused: Vec<String> = table().unwrap().into_keys().filter(|k| !used.contains(&k.as_str())).collect();
        assert!(unused.is_empty(), "meaning_zh.toml translates texts no parameter has:\n{}", unused.join("\n"));
    }
}
