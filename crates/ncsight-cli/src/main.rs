//! `ncsight`: a thin binary over the `ncsight-cli` library.

fn main() {
    let stdout = std::io::stdout();
    let stderr = std::io::stderr();
    // `ncsight lsp` speaks on standard output from its own thread: the handles stay unlocked.
    let code = if std::env::args_os().nth(1).is_some_and(|a| a == "lsp") {
        ncsight_cli::main_with(std::env::args_os(), &mut std::io::stdout(), &mut std::io::stderr())
    } else {
        ncsight_cli::main_with(std::env::args_os(), &mut stdout.lock(), &mut stderr.lock())
    };
    std::process::exit(code);
}
