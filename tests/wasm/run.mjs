// The engine compiled to WebAssembly (crates/ncsight-wasm), loaded as a page loads it, gives the
// JSONL of every golden programme exactly as `ncsight run --format jsonl` does
// (tests/golden/<case>/expected.jsonl), and a check gives diagnostics only.
//
//   cargo build -p ncsight-cli   (its build script builds the engine into target/engine)
//   node tests/wasm/run.mjs [path/to/ncsight_wasm.wasm]
import { readFileSync, readdirSync, existsSync } from "node:fs";
import { join, dirname } from "node:path";
import { fileURLToPath } from "node:url";

const root = join(dirname(fileURLToPath(import.meta.url)), "..", "..");
const wasmPath = process.argv[2] ?? join(root, "target", "engine", "wasm32-unknown-unknown", "release", "ncsight_wasm.wasm");
if (!existsSync(wasmPath)) {
  console.error(`wasm: ${wasmPath} is missing (cargo build -p ncsight-cli builds it, with the wasm32-unknown-unknown target installed)`);
  process.exit(1);
}
const { instance } = await WebAssembly.instantiate(readFileSync(wasmPath), {});
const { memory, ncsight_alloc, ncsight_free, ncsight_run } = instance.exports;

function put(bytes) {
  const p = ncsight_alloc(bytes.length);
  new Uint8Array(memory.buffer, p, bytes.length).set(bytes);
  return p;
}

/** The JSONL of a run (mode 0) or check (mode 1) of `text` on `machine` with `params` (N=V each)
 * and the text of a setup file (TOML; "" for none). */
function run(text, machine, mode, params = [], setup = "") {
  const p = new TextEncoder().encode(params.join("\n"));
  const s = new TextEncoder().encode(setup);
  const t = put(text);
  const m = put(new TextEncoder().encode(machine));
  const q = put(p);
  const u = put(s);
  const r = ncsight_run(t, text.length, m, machine.length, q, p.length, u, s.length, mode);
  const len = new DataView(memory.buffer).getUint32(r, true);
  const out = new TextDecoder().decode(new Uint8Array(memory.buffer, r + 4, len).slice());
  ncsight_free(r, 4 + len);
  ncsight_free(t, text.length);
  ncsight_free(m, machine.length);
  ncsight_free(q, p.length);
  ncsight_free(u, s.length);
  return out;
}

let cases = 0;
let failed = 0;
const golden = join(root, "tests", "golden");
for (const name of readdirSync(golden).sort()) {
  const dir = join(golden, name);
  if (!existsSync(join(dir, "input.nc"))) continue;
  const args = existsSync(join(dir, "args")) ? readFileSync(join(dir, "args"), "utf8").trim().split(/\s+/) : [];
  const machine = args.includes("--machine") ? args[args.indexOf("--machine") + 1] : "gsk980tdi";
  const params = args.flatMap((a, i) => (a === "--param" ? [args[i + 1]] : []));
  const setup = existsSync(join(dir, "setup.toml")) ? readFileSync(join(dir, "setup.toml"), "utf8") : "";
  const got = run(readFileSync(join(dir, "input.nc")), machine, 0, params, setup);
  const want = readFileSync(join(dir, "expected.jsonl"), "utf8");
  cases++;
  if (got !== want) {
    failed++;
    const g = got.split("\n"), w = want.split("\n");
    const i = g.findIndex((l, k) => l !== w[k]);
    console.error(`wasm: ${name}: line ${i + 1} differs\n  wasm: ${g[i]}\n  cli:  ${w[i]}`);
  }
}
const check = run(new TextEncoder().encode("G00 X0 Q1\nM30\n"), "gsk980tdi", 1);
if (!check.trim().split("\n").every((l) => JSON.parse(l).severity)) {
  failed++;
  console.error(`wasm: a check must give diagnostics only:\n${check}`);
}
const usage = JSON.parse(run(new TextEncoder().encode("G00 X0\n"), "haas", 0));
if (usage.kind !== "usage" || !usage.message.includes("unknown machine")) {
  failed++;
  console.error(`wasm: an unknown machine must be a usage line: ${JSON.stringify(usage)}`);
}
if (cases < 28) {
  failed++;
  console.error(`wasm: only ${cases} golden programmes found`);
}
console.log(`wasm: ${cases} golden programmes run in WebAssembly, ${failed} failed`);
process.exit(failed ? 1 : 0);
