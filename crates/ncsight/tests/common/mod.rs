//! What the integration tests share: run a programme on a machine with some parameters and
//! collect what the interpreter says.
#![allow(dead_code)]

use ncsight::profile::{self, Params};
use ncsight::{run_text_with, Diagnostic, Event, Mode, Options, Program, Record, Switches};

/// `machine` with its default parameters, each of `params` (`NAME=VALUE`) set on top.
pub fn params(machine: &str, params: &[&str]) -> Params {
    let mut p = Params::defaults(profile::by_name(machine).unwrap());
    for a in params {
        p.set_text(a).unwrap();
    }
    p
}

/// Every record and diagnostic of a programme's run.
pub fn split(events: impl Iterator<Item = Event>) -> (Vec<Record>, Vec<Diagnostic>) {
    let (mut records, mut diags) = (Vec::new(), Vec::new());
    for e in events {
        match e {
            Event::Record(r) => records.push(r),
            Event::Diagnostic(d) => diags.push(d),
        }
    }
    (records, diags)
}

/// `text` run on `machine` with the setup file `setup` (TOML), single block as asked.
pub fn run_setup(machine: &str, setup: &str, text: &str, single_block: bool) -> (Vec<Record>, Vec<Diagnostic>) {
    let operator = Options { single_block, ..Default::default() };
    let mut program = Program::with_operator(Params::defaults(profile::by_name(machine).unwrap()), Switches::default(), Mode::Run, operator);
    program.set_setup(&ncsight::setup::Setup::from_toml(setup).unwrap());
    split(ncsight::events(program, text.as_bytes()))
}

/// Every record and diagnostic of `text` run on `machine`.
pub fn run_with(machine: &str, given: &[&str], switches: Switches, opts: Options, text: &str) -> (Vec<Record>, Vec<Diagnostic>) {
    split(run_text_with(params(machine, given), switches, Mode::Run, opts, text.as_bytes()).into_iter())
}

/// The same with the default switches and options.
pub fn run_plain(machine: &str, given: &[&str], text: &str) -> (Vec<Record>, Vec<Diagnostic>) {
    run_with(machine, given, Switches::default(), Options::default(), text)
}

/// The first alarm of a plain run, if there is one.
pub fn first_alarm(machine: &str, text: &str) -> Option<Diagnostic> {
    let (_, d) = run_plain(machine, &[], text);
    d.into_iter().find(|d| d.is_alarm())
}

/// `text` on `machine` (with the setup `setup`, TOML, if given) through the push interface: each
/// event to a sink as it is made, as the command line takes them, where a block too big to hold
/// (a drilling block's holes, a roughing's levels) is made as it is handed on.
pub fn run_pushed(machine: &str, setup: Option<&str>, text: &str) -> (Vec<Record>, Vec<Diagnostic>) {
    let mut program = Program::with_operator(Params::defaults(profile::by_name(machine).unwrap()), Switches::default(), Mode::Run, Options::default());
    if let Some(s) = setup {
        program.set_setup(&ncsight::setup::Setup::from_toml(s).unwrap());
    }
    let mut events = Vec::new();
    for line in text.split_inclusive('\n') {
        program.feed_line(line.as_bytes(), &mut |e| events.push(e));
    }
    assert!(program.end_of_text(&mut |e| events.push(e)).is_none());
    split(events.into_iter())
}

/// The records of two paths are the same, one by one: block, move, single-block end, time.
pub fn same_records(got: &[Record], want: &[Record]) {
    assert_eq!(got.len(), want.len());
    for (k, (a, b)) in got.iter().zip(want).enumerate() {
        assert_eq!((a.span, a.op, a.block_end, a.t_s), (b.span, b.op, b.block_end, b.t_s), "record {k}");
    }
}
