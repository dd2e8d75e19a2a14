//! What each alarm and warning means, in English and Chinese (issue 36): its usual causes, how to
//! fix it, a wrong and a right example. One catalogue (`explain.toml`, written for ncsight, no
//! manual's text), read by `ncsight explain`, the page and docs/alarms.md; a test holds it
//! complete for every rule in both languages and runs every example.

use crate::alarm::Rule;
use serde::Deserialize;
use std::collections::BTreeMap;

/// One code's explanation.
#[derive(Debug, Clone, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Explanation {
    /// The title in Chinese, as a Chinese screen would show it beside the English
    /// [`Rule::title`] (`非法G代码`). Empty only where the catalogue lacks it (a test fails).
    #[serde(default)]
    pub title_zh: String,
    pub meaning_en: String,
    pub meaning_zh: String,
    pub causes_en: Vec<String>,
    pub causes_zh: Vec<String>,
    pub fix_en: String,
    pub fix_zh: String,
    /// A short programme that gives the code, and the same corrected, for `profile`.
    pub wrong: String,
    pub right: String,
    pub profile: String,
    /// What the wrong example needs beside the profile (`--param 3405.4=1`, a command other
    /// than `check`), where it needs something.
    #[serde(default)]
    pub options: Option<String>,
}

/// The language an explanation is given in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Lang {
    En,
    Zh,
}

const CATALOGUE: &str = include_str!("explain.toml");

/// The whole catalogue by project code (`NCS-E53`); an error names what is wrong with it (a
/// test keeps it right, so a release never meets one).
pub fn catalogue() -> Result<BTreeMap<String, Explanation>, String> {
    toml::from_str(CATALOGUE).map_err(|e| format!("the explanation catalogue: {e}"))
}

/// The rule a code names: its project code (`NCS-E53`, any case) or its FANUC number (`PS0063`).
pub fn rule_of(code: &str) -> Option<Rule> {
    let code = code.trim();
    Rule::ALL.iter().copied().find(|r| r.project_code().eq_ignore_ascii_case(code) || r.fanuc_code().is_some_and(|f| f.eq_ignore_ascii_case(code)))
}

/// The explanation of a code and its rule.
pub fn explain(code: &str) -> Option<(Rule, Explanation)> {
    let rule = rule_of(code)?;
    let entry = catalogue().ok()?.remove(rule.project_code())?;
    Some((rule, entry))
}

/// The explanation as text, in `lang` (the English title and codes in both; in Chinese the
/// Chinese title after the English one).
pub fn render(rule: Rule, e: &Explanation, lang: Lang) -> String {
    let mut s = String::new();
    let fanuc = rule.fanuc_code().map(|f| format!(" / FANUC {f}")).unwrap_or_default();
    let kind = match (rule.severity(), lang) {
        (crate::alarm::Severity::Alarm, Lang::En) => "alarm",
        (crate::alarm::Severity::Warning, Lang::En) => "warning",
        (crate::alarm::Severity::Alarm, Lang::Zh) => "报警",
        (crate::alarm::Severity::Warning, Lang::Zh) => "警告",
    };
    let title_zh = match lang {
        Lang::Zh if !e.title_zh.trim().is_empty() => format!(" {}", e.title_zh.trim()),
        _ => String::new(),
    };
    s.push_str(&format!("{}{fanuc} ({kind}): {}{title_zh}\n\n", rule.project_code(), rule.title()));
    let (meaning, causes, fix, heads) = match lang {
        Lang::En => (&e.meaning_en, &e.causes_en, &e.fix_en, ["Usual causes", "How to fix it", "Wrong", "Right"]),
        Lang::Zh => (&e.meaning_zh, &e.causes_zh, &e.fix_zh, ["常见原因", "解决办法", "错误示例", "正确示例"]),
    };
    s.push_str(meaning);
    s.push_str(&format!("\n\n{}:\n", heads[0]));
    for c in causes {
        s.push_str(&format!("- {c}\n"));
    }
    s.push_str(&format!("\n{}: {fix}\n", heads[1]));
    let indent = |t: &str| t.lines().map(|l| format!("    {l}\n")).collect::<String>();
    let with = e.options.as_deref().map(|o| format!(", {o}")).unwrap_or_default();
    s.push_str(&format!("\n{} ({}{with}):\n{}", heads[2], e.profile, indent(&e.wrong)));
    s.push_str(&format!("\n{}:\n{}", heads[3], indent(&e.right)));
    s
}
