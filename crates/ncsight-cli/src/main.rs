//! `ncsight`: a thin binary over the `ncsight-cli` library.

fn main() {
    let stdout = std::io::stdout();
    let stderr = std::io::stderr();
    let code = ncsight_cli::main_with(std::env::args_os(), &mut stdout.lock(), &mut stderr.lock());
    std::process::exit(code);
}
