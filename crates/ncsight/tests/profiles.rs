//! A new profile is data: one `Profile` value (its tables, rules and parameters) and its
//! registration. This test adds one outside the crate, a lathe that reuses the GSK980TDi's rule
//! tables under another name, and runs the GSK980TDi manual's O0012 on it: the interpreter asks
//! the profile and never which controller it is, so the records are the same.

use ncsight::profile::{self, Params, Profile};
use ncsight::{run_text, Event, Mode, Switches};

fn records(profile: &'static Profile, text: &str) -> Vec<Event> {
    run_text(Params::defaults(profile), Switches::default(), Mode::Run, text.as_bytes())
}

#[test]
fn a_profile_defined_as_data_runs_o0012() {
    let base = profile::by_name("gsk980tdi").unwrap();
    let test_lathe: &'static Profile = Box::leak(Box::new(Profile { name: "test-lathe", title: "a test lathe with the GSK980TDi's rules", ..base.clone() }));
    test_lathe.validate().unwrap();
    let o0012 = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/gsk980tdi_o0012.nc")).unwrap();
    let ours = records(test_lathe, &o0012);
    let theirs = records(base, &o0012);
    assert_eq!(ours, theirs);
    // Four passes of G92, each a thread with its pull-out, and no alarm.
    let threads = ours.iter().filter(|e| matches!(e, Event::Record(r) if r.op.is_thread())).count();
    assert_eq!(threads, 8, "four passes, each a thread and its pull-out");
    assert!(!ours.iter().any(|e| matches!(e, Event::Diagnostic(d) if d.is_alarm())));
    // Its parameters are its own: a parameter set on the test lathe changes its run only.
    let mut params = Params::defaults(test_lathe);
    params.set_text("rapid_accel_ms=300").unwrap();
    let slower = run_text(params, Switches::default(), Mode::Run, o0012.as_bytes());
    assert!(slower != theirs, "the setting changes the times");
    assert_eq!(records(base, &o0012), theirs);
}

/// A profile whose data do not hold together is refused before it runs: a G92 whose rules name
/// a parameter the profile does not define.
#[test]
fn a_profile_with_a_missing_parameter_is_refused() {
    use ncsight::profile::{CycleRules, GDef, GFn, Group, HoldRule, JkWords, ParamKey, PullOutRule, ThreadCmd};
    static RULES: CycleRules = CycleRules {
        code: "G92",
        rigid: false,
        negative_f_left_hand: false,
        lead_i: false,
        lead_e: false,
        repair_p: false,
        starts_l: false,
        jk: JkWords::None,
        flank_k: false,
        ts_before: false,
        q_start: false,
        taper: b'R',
        taper_limit: true,
        pull_out: PullOutRule::Chamfer { amount: ParamKey::Number(4242, None), angle: ParamKey::Number(4243, None) },
        hold: HoldRule::AfterRun,
    };
    static G93: &[GDef] =
        &[GDef { major: 93, minor: None, name: "G93", group: Group::Motion, function: GFn::Thread(ThreadCmd::Cycle(&RULES)), meaning: "test" }];
    let base = profile::by_name("fanuc0m").unwrap();
    let mut codes: Vec<profile::Codes<GDef>> = base.g_codes.to_vec();
    codes.push(profile::Codes { source: "test", codes: G93 });
    let broken: &'static Profile = Box::leak(Box::new(Profile { name: "broken", g_codes: Box::leak(codes.into_boxed_slice()), ..base.clone() }));
    let e = broken.validate().unwrap_err();
    assert!(e.contains("4242"), "{e}");
}

/// Every code in a profile's tables is known to it: written alone in a block it never gets
/// "no such code" (IMPROPER G-CODE; for an M code, the machine-specific warning), and it gets "not simulated yet"
/// (NCS-E38) exactly when its table says so (the status `ncsight machines NAME` prints).
#[test]
fn every_code_of_a_table_is_known_and_its_status_holds() {
    use ncsight::profile::CodeStatus;
    for p in profile::all() {
        for g in p.g_defs() {
            // The GSK980TDi's G10 has the forms L3 and L52 only; bare, it is IMPROPER G-CODE.
            let block = if g.function == profile::GFn::DataSetting && p.frame.g10 == profile::G10Forms::ToolLifeAndParameters { "G10 L3" } else { g.name };
            // Scaling is an option the machine declares (without it G50/G51 are IMPROPER G-CODE,
            // as on the FANUC): the code is known, the test machine has the option.
            let mut params = Params::defaults(p);
            if let (profile::GFn::Scaling(_), Some(profile::ParamKey::Setting(name))) = (g.function, p.frame.transform_keys.scaling_option) {
                params.set_text(&format!("{name}=1")).unwrap();
            }
            let events = run_text(params, Switches::default(), Mode::Check, format!("{block}\nM30\n").as_bytes());
            let codes: Vec<&str> = events.iter().filter_map(|e| if let Event::Diagnostic(d) = e { d.is_alarm().then_some(d.code) } else { None }).collect();
            let e10 = ncsight::Rule::ImproperGCode.code(p.alarm_style);
            assert!(!codes.contains(&e10), "{} {}: {codes:?}", p.name, g.name);
            let not_yet = codes.contains(&"NCS-E38");
            assert_eq!(not_yet, p.code_status(g) == CodeStatus::NotYet, "{} {}: {codes:?}", p.name, g.name);
        }
        for m in p.m_defs() {
            let events = run_text(Params::defaults(p), Switches::default(), Mode::Check, format!("M{:02}\nM30\n", m.code).as_bytes());
            let codes: Vec<&str> = events.iter().filter_map(|e| if let Event::Diagnostic(d) = e { Some(d.code) } else { None }).collect();
            // An M code the table lacks is a machine builder's: NCS-W05.
            assert!(!codes.contains(&"NCS-W05"), "{} M{}: {codes:?}", p.name, m.code);
        }
    }
}
