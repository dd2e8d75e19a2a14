//! The explanation catalogue (issue 36): every rule explained in English and Chinese, and every
//! example does what it says: the wrong one gives its code on its profile, the right one does not.

use ncsight::explain::{catalogue, Explanation};
use ncsight::profile::{self, Params};
use ncsight::{Event, Mode, Rule, Switches};

/// Codes whose situation no short programme can give (a line over 4,096 bytes, a block of more
/// motions than ncsight keeps, the runaway guard): their `wrong` shows the situation in small.
const NOT_BY_A_SHORT_EXAMPLE: &[&str] = &["NCS-E31", "NCS-E40", "NCS-E63"];

/// The `--param K=V` settings of an example's options; `None` where it needs more than
/// parameters (a setup, another command): such an example is run by the command line's tests.
fn params_of(options: Option<&str>) -> Option<Vec<String>> {
    let Some(o) = options else { return Some(Vec::new()) };
    let words: Vec<&str> = o.split_whitespace().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < words.len() {
        if words[i] != "--param" || i + 1 >= words.len() {
            return None;
        }
        out.push(words[i + 1].to_string());
        i += 2;
    }
    Some(out)
}

fn codes_of(profile_name: &str, params: &[String], text: &str) -> Vec<&'static str> {
    let p = profile::by_name(profile_name).unwrap_or_else(|| panic!("no profile {profile_name}"));
    let mut values = Params::defaults(p);
    for a in params {
        values.set_text(a).unwrap_or_else(|e| panic!("{a}: {e:?}"));
    }
    let events = ncsight::run_text(values, Switches::default(), Mode::Check, text.as_bytes());
    events.iter().filter_map(|e| if let Event::Diagnostic(d) = e { Some(d.code) } else { None }).collect()
}

fn has_chinese(s: &str) -> bool {
    s.chars().any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c))
}

#[test]
fn every_rule_is_explained_in_both_languages() {
    let cat = catalogue().unwrap();
    for r in Rule::ALL {
        let e: &Explanation = cat.get(r.project_code()).unwrap_or_else(|| panic!("{} has no explanation", r.project_code()));
        let code = r.project_code();
        for (what, text) in [("meaning_en", &e.meaning_en), ("fix_en", &e.fix_en), ("wrong", &e.wrong), ("right", &e.right)] {
            assert!(!text.trim().is_empty(), "{code}: {what} is empty");
        }
        for (what, text) in [("title_zh", &e.title_zh), ("meaning_zh", &e.meaning_zh), ("fix_zh", &e.fix_zh)] {
            assert!(has_chinese(text), "{code}: {what} is missing, empty or has no Chinese");
        }
        assert!((1..=3).contains(&e.causes_en.len()) && e.causes_en.len() == e.causes_zh.len(), "{code}: causes in both languages, one to three");
        assert!(e.causes_zh.iter().all(|c| has_chinese(c)) && e.causes_en.iter().all(|c| !c.trim().is_empty()), "{code}: a cause is empty");
        assert!(profile::by_name(&e.profile).is_some(), "{code}: no profile {}", e.profile);
    }
    let mut titles: Vec<(&str, &str)> = cat.iter().map(|(k, e)| (e.title_zh.trim(), k.as_str())).collect();
    titles.sort();
    for w in titles.windows(2) {
        assert!(w[0].0 != w[1].0, "{} and {}: the same title_zh {:?}", w[0].1, w[1].1, w[0].0);
    }
    let known: Vec<&str> = Rule::ALL.iter().map(|r| r.project_code()).collect();
    for k in cat.keys() {
        assert!(known.contains(&k.as_str()), "{k}: explained, but no rule has this code");
    }
}

/// The Chinese text shows the Chinese title after the English one; the English text does not.
#[test]
fn chinese_title_follows_the_english_one() {
    let (rule, e) = ncsight::explain::explain("PS0010").unwrap();
    let zh = ncsight::explain::render(rule, &e, ncsight::explain::Lang::Zh);
    assert!(zh.starts_with("NCS-E10 / FANUC PS0010 (报警): IMPROPER G-CODE 非法G代码\n"), "{zh}");
    let en = ncsight::explain::render(rule, &e, ncsight::explain::Lang::En);
    assert!(en.starts_with("NCS-E10 / FANUC PS0010 (alarm): IMPROPER G-CODE\n"), "{en}");
}

#[test]
fn every_example_gives_its_code_and_its_correction_does_not() {
    let cat = catalogue().unwrap();
    let mut failed = Vec::new();
    for r in Rule::ALL {
        let code = r.project_code();
        let Some(e) = cat.get(code) else { continue };
        let p = profile::by_name(&e.profile).unwrap();
        let shown = r.code(p.alarm_style);
        let params = params_of(e.options.as_deref());
        if let (false, Some(params)) = (NOT_BY_A_SHORT_EXAMPLE.contains(&code), &params) {
            let got = codes_of(&e.profile, params, &e.wrong);
            if !got.contains(&shown) {
                failed.push(format!("{code}: the wrong example on {} gives {got:?}, not {shown}:\n{}", e.profile, e.wrong));
            }
        }
        let got = codes_of(&e.profile, params.as_deref().unwrap_or(&[]), &e.right);
        if got.contains(&shown) {
            failed.push(format!("{code}: the right example on {} still gives {shown}:\n{}", e.profile, e.right));
        }
    }
    assert!(failed.is_empty(), "{}", failed.join("\n\n"));
}
