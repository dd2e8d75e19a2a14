//! The alarms' explanations (`ncsight explain`'s catalogue), read once.

use ncsight::explain::{catalogue, Explanation};
use std::collections::BTreeMap;
use std::sync::OnceLock;

fn all() -> &'static BTreeMap<String, Explanation> {
    static CATALOGUE: OnceLock<BTreeMap<String, Explanation>> = OnceLock::new();
    // A test in the core holds the catalogue well formed; should it not be, nothing is explained.
    CATALOGUE.get_or_init(|| catalogue().unwrap_or_default())
}

/// What a code means, in English (by its project code, `NCS-E53`).
pub fn meaning_en(project_code: &str) -> Option<&'static str> {
    all().get(project_code).map(|e| e.meaning_en.as_str())
}
