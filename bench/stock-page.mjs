// The page's engine (WebAssembly) cutting a stock as the page's worker asks it to
// (`ncsight_stock`): node bench/stock-page.mjs ENGINE.wasm PROGRAMME MACHINE SETUP.toml [OPTIONS].
// Prints the answer's header; bench/stock times it.
import { readFileSync } from "node:fs";

const [wasm, programme, machine, setup, options = ""] = process.argv.slice(2);
const { instance } = await WebAssembly.instantiate(readFileSync(wasm), {});
const E = instance.exports;
const enc = new TextEncoder();
const bufs = [readFileSync(programme), enc.encode(machine), enc.encode(""), readFileSync(setup), enc.encode(options), new Uint8Array(0)];
const ptrs = bufs.map((b) => {
  const p = E.ncsight_alloc(b.length) >>> 0;
  new Uint8Array(E.memory.buffer, p, b.length).set(b);
  return p;
});
const args = [];
ptrs.forEach((p, i) => args.push(p, bufs[i].length));
const at = E.ncsight_stock(...args) >>> 0;
const len = new DataView(E.memory.buffer).getUint32(at, true);
const out = new Uint8Array(E.memory.buffer.slice(at + 4, at + 4 + len));
const magic = new TextDecoder().decode(out.subarray(0, 4));
if (magic !== "NCST") {
  console.error(new TextDecoder().decode(out));
  process.exit(1);
}
const jl = new DataView(out.buffer).getUint32(4, true);
console.log(new TextDecoder().decode(out.subarray(8, 8 + jl)));
