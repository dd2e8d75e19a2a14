// Drives ncsight's page (`ncsight app`, `ncsight report`) in a real headless Chromium (the
// system's, Debian package `chromium`): the engine in the page runs the programme; the plot, the
// player, the source, the operator panel, the languages, files dropped on it, and the sizes the
// page must stay quick at. Screenshots of each view are kept in artifacts/ and looked at as pixels.
//
// Run: npm install && npm test (the ncsight binary must be built: cargo build).
import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { mkdirSync, mkdtempSync, writeFileSync, readFileSync, existsSync, statSync } from "node:fs";
import { join, resolve } from "node:path";
import { tmpdir } from "node:os";
import { chromium } from "playwright-core";
import { decodePng, count } from "./png.mjs";

/** Pixels of a screenshot for which `f([r, g, b])` holds. */
function pixels(img, f) {
  let n = 0;
  for (let y = 0; y < img.height; y++) for (let x = 0; x < img.width; x++) if (f(img.at(x, y))) n++;
  return n;
}
// The 3D view's colours, lit: the section of the cut-away (orange), the mill's cut floors (the
// block's grey turning blue with depth), a finding's ball (red).
const orange = ([r, g, b]) => r > g + 30 && g > b + 30;
const blue = ([r, g, b]) => b > r + 35 && b > 120;
const red = ([r, g, b]) => r > 170 && g < 60 && b < 60;

const root = resolve(import.meta.dirname, "../..");
const bin = [join(root, "target/release/ncsight"), join(root, "target/debug/ncsight")].find(existsSync);
const browserPath = process.env.CHROMIUM || "/usr/bin/chromium";
const artifacts = join(import.meta.dirname, "artifacts");
const work = mkdtempSync(join(tmpdir(), "ncsight-page-"));
let browser;

function ncsight(args) {
  assert.ok(bin, "build ncsight first (cargo build)");
  try {
    execFileSync(bin, args, { stdio: "pipe" });
  } catch (e) {
    // Exit 1 (an alarm) and 3 (a finding of the stock simulation) still write the page.
    if (e.status !== 1 && e.status !== 3) throw e;
  }
}
function report(programme, machine, extra = []) {
  const out = join(work, `${Math.random().toString(36).slice(2)}.html`);
  ncsight(["report", programme, "--machine", machine, "-o", out, ...extra]);
  return out;
}

async function open(file, options = {}) {
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 }, locale: options.locale || "en-GB" });
  const page = await context.newPage();
  const requests = [], dialogs = [], errors = [];
  page.on("request", (r) => requests.push(r.url()));
  page.on("dialog", (d) => { dialogs.push(d.message()); d.dismiss(); });
  page.on("pageerror", (e) => errors.push(String(e)));
  const t0 = Date.now();
  await page.goto("file://" + file, { timeout: 60000 });
  await page.evaluate(() => window.ncsightApp.ready);
  // The page's own clock: from navigation to the end of the first drawing of the path.
  const shownMs = Math.round((await page.evaluate(() => window.ncsightApp.firstPathMs)) || Date.now() - t0);
  return { page, context, requests, dialogs, errors, shownMs };
}
/** Evaluate `f` in the page once every run started so far is shown: the engine runs in a Web
 * Worker, so a change (a key, a switch) shows a moment later. */
const app = async (page, f, arg) => {
  await page.evaluate(() => window.ncsightApp.settled());
  return page.evaluate(f, arg);
};
/** Wait until `f` holds in the page (polled: the page's policy forbids the evaluated strings
 * waitForFunction uses). */
async function until(page, f, arg, ms = 15000) {
  const end = Date.now() + ms;
  while (!(await page.evaluate(f, arg))) {
    if (Date.now() > end) throw new Error(`timed out waiting for ${f}`);
    await new Promise((r) => setTimeout(r, 50));
  }
}
async function shot(page, name, selector) {
  const path = join(artifacts, name);
  if (selector) await (await page.$(selector)).screenshot({ path });
  else await page.screenshot({ path });
  return decodePng(readFileSync(path));
}
/** The quickest of three zoom steps and of three player steps (block by block), in ms. */
const stepTimes = async (page) => (await page.evaluate(() => window.ncsightApp.settled()), page.evaluate(() => {
  const a = window.ncsightApp, time = (f) => { const t0 = performance.now(); f(); return performance.now() - t0; };
  const zoom = Math.min(time(() => a.zoom(1.25)), time(() => a.zoom(1.25)), time(() => a.zoom(0.8)));
  a.setTime(a.scene.head.total_s / 2);
  const step = Math.min(time(() => a.stepBlock(1)), time(() => a.stepBlock(1)), time(() => a.stepBlock(-1)));
  return { zoom, step };
}));
const o0012 = readFileSync(join(root, "examples/gsk980tdi_o0012.nc"), "utf8");

before(async () => {
  mkdirSync(artifacts, { recursive: true });
  browser = await chromium.launch({
    executablePath: browserPath,
    // WebGL (the 3D view) in software: SwiftShader through ANGLE, as on a machine with no GPU.
    args: ["--no-sandbox", "--disable-gpu", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-quic", "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync"],
  });
});
after(async () => { if (browser) await browser.close(); });

test("ncsight app: choose the controller, paste O0012, four passes; F0 is an alarm without a reload", async () => {
  const file = join(work, "app.html");
  ncsight(["app", "-o", file]);
  const { page, context, requests, errors } = await open(file);
  assert.deepEqual(errors, []);
  assert.equal(await app(page, () => window.ncsightApp.scene), null);
  await page.selectOption("#machine", "gsk980tdi");
  await app(page, () => { window.__same_page = true; });
  await page.fill("#text", o0012);
  await until(page, () => window.ncsightApp.scene && window.ncsightApp.passes() === 4);
  assert.match(await page.textContent("#banner"), /No problems: ended at 0:12\.1/);
  await shot(page, "app-o0012.png");
  // F3 -> F0 in the G92 block: the controller's alarm, in the banner, the list and the gutter.
  await page.fill("#text", o0012.replace("F3", "F0"));
  await until(page, () => window.ncsightApp.scene && window.ncsightApp.scene.head.status === "alarm");
  assert.equal(await app(page, () => window.__same_page), true);
  const banner = await page.textContent("#banner");
  assert.match(banner, /1 alarm/);
  assert.match(await page.textContent("#problems"), /line 4 .*F/);
  assert.equal(await page.$$eval('#gutter-rows .g.alarm[data-line="4"]', (g) => g.length), 1);
  await shot(page, "app-alarm.png");
  // Two typos: the run stops at the first, as the controller does; the check goes on and lists both.
  await page.fill("#text", "G0 X10 Z5\nG0 X10 Q1\nG0 X20 Q1\nM30\n");
  await until(page, () => window.ncsightApp.scene && window.ncsightApp.scene.head.diagnostics.length === 2);
  const listed = await page.$$eval("#problems .p.alarm", (p) => p.map((e) => e.getAttribute("data-line")));
  assert.deepEqual(listed, ["2", "3"]);
  assert.match(await page.textContent("#banner"), /^2 alarm\(s\), 0 warning\(s\)/);
  assert.match(await page.textContent('#problems .p[data-line="3"]'), /found by the check/);
  assert.equal(await page.$$eval('#gutter-rows .g.alarm[data-line="3"]', (g) => g.length), 1);
  // Between motions the player names the record under way: a dwell is line 2, not the next move.
  await page.fill("#text", "G0 X10 Z5\nG04 X2.\nG0 X20 Z5\nM30\n");
  await until(page, () => window.ncsightApp.scene && window.ncsightApp.scene.n === 2);
  const dwellAt = await app(page, () => { const e = window.ncsightApp.scene.head.events.find((x) => x.k === "dwell"); return e.t - 1; });
  await app(page, (t) => window.ncsightApp.setTime(t), dwellAt);
  assert.equal(await app(page, () => window.ncsightApp.runLine), 2);
  assert.match(await page.textContent("#state"), /dwell/);
  // Nothing goes to the network: the page's own file, data: images and the engine's worker
  // (a blob: URL the page makes from its own script).
  assert.deepEqual(requests.filter((u) => !u.startsWith("file://") && !u.startsWith("data:") && !u.startsWith("blob:null/")), []);
  await context.close();
});

test("report O0012: the thread, the player follows the source, a click in the plot selects the block", async () => {
  const { page, context, errors } = await open(report(join(root, "examples/gsk980tdi_o0012.nc"), "gsk980tdi", ["--stock", "60x80"]));
  assert.deepEqual(errors, []);
  assert.equal(await app(page, () => window.ncsightApp.passes()), 4);
  assert.match(await page.textContent("#thread"), /minor diameter\s*56\.900 mm/);
  // From the start, block by block: the running line is highlighted in the source.
  await page.keyboard.press("Home");
  await page.click("#next");
  await page.click("#next");
  await page.click("#next");
  const line = await app(page, () => window.ncsightApp.runLine);
  assert.ok(line >= 2 && line <= 4, `running line ${line}`);
  assert.equal(await page.$$eval(`#overlay .o.run[data-line="${line}"]`, (o) => o.length), 1);
  const ed = await shot(page, "report-step.png", "#editor");
  const box = await page.$eval(`#overlay .o.run[data-line="${line}"]`, (o) => { const r = o.getBoundingClientRect(), e = document.getElementById("editor").getBoundingClientRect(); return [r.top - e.top, r.height]; });
  const lit = count(ed, [255, 224, 130], 10, 70, Math.round(box[0]) + 2, ed.width, Math.round(box[0] + box[1]) - 2);
  assert.ok(lit > 2000, `running line's highlight: ${lit} pixels`);
  // Each press of Block goes on in time.
  const t1 = await app(page, () => window.ncsightApp.now);
  await page.click("#next");
  assert.ok((await app(page, () => window.ncsightApp.now)) > t1);
  // A click on the second pass (X57.7 from Z5 to Z-28, at Z-10) selects line 5.
  const [x, y] = await app(page, () => window.ncsightApp.toScreen(57.7 / 2, 0, -10));
  const canvas = await page.$eval("#plot", (c) => { const r = c.getBoundingClientRect(); return [r.left, r.top]; });
  // Hovering it names the block.
  await page.mouse.move(canvas[0] + x, canvas[1] + y);
  await until(page, () => !document.getElementById("tip").hidden);
  assert.match(await page.textContent("#tip"), /^line 5: thread/);
  await page.mouse.click(canvas[0] + x, canvas[1] + y);
  assert.equal(await app(page, () => window.ncsightApp.selLine), 5);
  // The operator panel: FEED HOLD in the middle of a pass runs the programme again with it.
  const before = await app(page, () => window.ncsightApp.scene.head.total_s);
  await app(page, () => window.ncsightApp.setTime(4.5));
  await page.click("#hold");
  assert.match(await page.textContent("#presses"), /FEED HOLD at 4\.50 s/);
  assert.notEqual(await app(page, () => window.ncsightApp.scene.head.total_s), before);
  // The hold parameter (GSK980TDi NO.18 bit 6): set in the parameter table, the same press
  // finishes the pass before stopping instead of pulling out at once.
  const pulledOut = await app(page, () => window.ncsightApp.scene.head.total_s);
  await page.click("#params-box summary");
  await page.check('#param-table input[data-param="18.6"]');
  assert.match(await page.inputValue("#params"), /^18\.6=1$/m);
  const finished = await app(page, () => window.ncsightApp.scene.head.total_s);
  assert.notEqual(finished, pulledOut);
  assert.equal(await page.isChecked('#param-table input[data-param="18.6"]'), true);
  await page.uncheck('#param-table input[data-param="18.6"]');
  assert.match(await page.inputValue("#params"), /^18\.6=0$/m);
  await page.click("#clear-buttons");
  assert.equal(await app(page, () => window.ncsightApp.scene.head.total_s), before);
  // Time by tool, as a person reads it.
  assert.match(await page.textContent("#time-by-tool"), /T01 螺纹刀\s*0:12\.1/); // named by its comment
  await context.close();
});

test("every control: play, speed, next tool, run to cursor, keys, zoom, pan, fit, panel switches, open a file", async () => {
  const { page, context, errors } = await open(report(join(root, "examples/gsk980tdi_g71_g70_part.nc"), "gsk980tdi", ["--stock", "32x60"]));
  assert.deepEqual(errors, []);
  const A = (f, arg) => app(page, f, arg);
  const total = await A(() => window.ncsightApp.scene.head.total_s);
  // Keys (focus on the page, not the editor): Home, End, arrows.
  await page.click("#state");
  await page.keyboard.press("Home");
  assert.equal(await A(() => window.ncsightApp.now), 0);
  await page.keyboard.press("ArrowRight");
  const firstStop = await A(() => window.ncsightApp.now);
  assert.ok(firstStop > 0);
  await page.keyboard.press("End");
  assert.equal(await A(() => window.ncsightApp.now), total);
  await page.keyboard.press("ArrowLeft");
  assert.ok((await A(() => window.ncsightApp.now)) < total);
  // T: the next tool; + and -: zoom about the middle; F: fit again; space: play and pause.
  await page.keyboard.press("Home");
  await page.keyboard.press("t");
  assert.equal(await A(() => window.ncsightApp.runLine), 16);
  const fitted = await A(() => window.ncsightApp.toScreen(10, 0, -20));
  await page.keyboard.press("+");
  assert.notDeepEqual(await A(() => window.ncsightApp.toScreen(10, 0, -20)), fitted);
  await page.keyboard.press("-");
  await page.keyboard.press("-");
  await page.keyboard.press("f");
  assert.deepEqual(await A(() => window.ncsightApp.toScreen(10, 0, -20)), fitted);
  await page.keyboard.press("Home");
  await page.keyboard.press(" ");
  await new Promise((r) => setTimeout(r, 200));
  await page.keyboard.press(" ");
  const spaced = await A(() => window.ncsightApp.now);
  assert.ok(spaced > 0 && spaced < total, `space played to ${spaced} s`);
  // CYCLE START at 20x, then pause: time went on, and stays.
  await page.keyboard.press("Home");
  await page.selectOption("#speed", "20");
  await page.click("#play");
  assert.equal(await A(() => window.ncsightApp.machineState), "run");
  await new Promise((r) => setTimeout(r, 300));
  await page.click("#pause");
  const played = await A(() => window.ncsightApp.now);
  assert.ok(played > 1 && played < total, `played to ${played} s`);
  await new Promise((r) => setTimeout(r, 100));
  assert.equal(await A(() => window.ncsightApp.now), played);
  assert.equal(await A(() => window.ncsightApp.machineState), "stop");
  // Next tool: from the start (T0101 is in place at 0 s), T0303 on line 16.
  await page.keyboard.press("Home");
  await page.click("#next-tool");
  assert.equal(await A(() => window.ncsightApp.runLine), 16);
  // Run to the cursor: the caret on line 12 (X28.).
  await A(() => { const ta = document.getElementById("text"); const at = ta.value.split("\n").slice(0, 11).join("\n").length + 1; ta.focus(); ta.setSelectionRange(at, at); });
  await page.keyboard.press("Home"); // in the editor: the caret's own key, not the player's
  await A(() => window.ncsightApp.setTime(0));
  await page.click("#to-cursor");
  assert.equal(await A(() => window.ncsightApp.runLine), 12);
  // Zoom with the buttons and the wheel, pan by dragging, fit again.
  const at0 = await A(() => window.ncsightApp.toScreen(10, 0, -20));
  await page.click("#zoom-in");
  const at1 = await A(() => window.ncsightApp.toScreen(10, 0, -20));
  assert.notDeepEqual(at1, at0);
  const box = await page.$eval("#plot", (c) => { const r = c.getBoundingClientRect(); return [r.left, r.top, r.width, r.height]; });
  await page.mouse.move(box[0] + box[2] / 2, box[1] + box[3] / 2);
  await page.mouse.wheel(0, -300);
  const at2 = await A(() => window.ncsightApp.toScreen(10, 0, -20));
  assert.notDeepEqual(at2, at1);
  await page.mouse.down();
  await page.mouse.move(box[0] + box[2] / 2 + 80, box[1] + box[3] / 2 + 30, { steps: 4 });
  await page.mouse.up();
  const at3 = await A(() => window.ncsightApp.toScreen(10, 0, -20));
  assert.ok(Math.abs(at3[0] - at2[0] - 80) < 2 && Math.abs(at3[1] - at2[1] - 30) < 2, `panned ${at2} -> ${at3}`);
  await page.click("#fit");
  assert.deepEqual(await A(() => window.ncsightApp.toScreen(10, 0, -20)), at0);
  // The panel: feed override 50 % and dry run each run the programme again.
  await page.selectOption("#feed-ov", "50");
  const slower = await A(() => window.ncsightApp.scene.head.total_s);
  assert.ok(slower > total * 1.3, `${slower} s at 50 % against ${total} s`);
  await page.selectOption("#feed-ov", "100");
  await page.check("#dry");
  assert.notEqual(await A(() => window.ncsightApp.scene.head.total_s), total);
  await page.uncheck("#dry");
  await page.selectOption("#rapid-ov", "25");
  assert.ok((await A(() => window.ncsightApp.scene.head.total_s)) > total, "rapids at 25 %");
  await page.selectOption("#rapid-ov", "100");
  const before = await A(() => window.ncsightApp.runs);
  await page.check("#single");
  assert.equal(await A(() => window.ncsightApp.runs), before + 1);
  assert.ok((await A(() => window.ncsightApp.scene.head.total_s)) >= total);
  await page.uncheck("#single");
  assert.equal(await A(() => window.ncsightApp.runs), before + 2);
  assert.equal(await A(() => window.ncsightApp.scene.head.total_s), total);
  // A parameter: the G71 retract by parameter instead of R... any change runs it again.
  const runs = await A(() => window.ncsightApp.runs);
  await page.fill("#params", "19=10");
  await page.dispatchEvent("#params", "change");
  assert.ok((await A(() => window.ncsightApp.runs)) > runs);
  // Open a file (GBK, as a GSK controller saves it).
  const gbk = join(work, "open-gbk.nc");
  writeFileSync(gbk, Buffer.concat([Buffer.from("G0 X20. Z2. (", "latin1"), Buffer.from([0xb5, 0xb6, 0xbe, 0xdf]), Buffer.from(")\nG1 Z-10. F0.2\nM30\n", "latin1")]));
  await page.setInputFiles("#file", gbk);
  await until(page, () => document.getElementById("file-name").textContent === "open-gbk.nc" && window.ncsightApp.scene.n === 2);
  assert.match(await page.inputValue("#text"), /\(刀具\)/);
  // The stock typed in: the part is drawn from it (Ø40 beyond the cut, Ø20 where G1 turned it).
  await page.fill("#stock", "40x30");
  await page.dispatchEvent("#stock", "change");
  const radii = await A(() => window.ncsightApp.part());
  assert.equal(radii[0], 20);
  assert.equal(radii[radii.length - 1], 10);
  assert.deepEqual(errors, []);
  await shot(page, "app-controls.png");
  await context.close();
});

test("G71/G70 with --stock: axes, ticks and the turned part as a mirrored half-section", async () => {
  const { page, context, errors } = await open(report(join(root, "examples/gsk980tdi_g71_g70_part.nc"), "gsk980tdi", ["--stock", "32x60"]));
  assert.deepEqual(errors, []);
  await app(page, () => window.ncsightApp.zoom(0.6));
  const img = await shot(page, "report-g71-part.png", "#plot");
  // The spindle centre line (dash-dot) through the work zero, across the plot.
  const [, axisY] = await app(page, () => window.ncsightApp.toScreen(0, 0, 0));
  const centre = count(img, [69, 90, 100], 20, 0, Math.round(axisY) - 1, img.width, Math.round(axisY) + 2);
  assert.ok(centre > 300, `centre line: ${centre} pixels`);
  // The part, shaded on both sides of the axis: Ø24 at Z-20 above, its mirror below.
  const shade = [196, 206, 212];
  const [px, up] = await app(page, () => window.ncsightApp.toScreen(8, 0, -20));
  const [, down] = await app(page, () => window.ncsightApp.toScreen(-8, 0, -20));
  assert.ok(count(img, shade, 8, px - 20, up - 10, px + 20, up + 10) > 200, "the part above the axis");
  assert.ok(count(img, shade, 8, px - 20, down - 10, px + 20, down + 10) > 200, "its mirror below");
  // Cut away above Ø24 there (Ø28 at Z-20 is outside the part).
  const [, cut] = await app(page, () => window.ncsightApp.toScreen(13.5, 0, -20));
  assert.equal(count(img, shade, 8, px - 3, cut - 2, px + 3, cut + 2), 0);
  // The part follows the player: at the start nothing is cut.
  await app(page, () => window.ncsightApp.setTime(0));
  const start = await shot(page, "report-g71-start.png", "#plot");
  assert.ok(count(start, shade, 8, px - 3, cut - 2, px + 3, cut + 2) > 15);
  // Tick labels along the bottom (a font's dark pixels in the label strip).
  assert.ok(count(img, [55, 71, 79], 40, 50, img.height - 14, img.width, img.height) > 100);
  // The part as a solid: its lit front face (the end at Z0) and the shaded body.
  await app(page, () => window.ncsightApp.setTime(window.ncsightApp.scene.head.total_s));
  await page.selectOption("#view", "part3d");
  const solid = await shot(page, "report-g71-part3d.png", "#plot");
  // The front face (the end at Z0), lit flat, around the axis.
  const [fx, fy] = (await app(page, () => window.ncsightApp.toScreen(0, 0, 0))).map(Math.round);
  assert.ok(count(solid, [207, 216, 220], 3, fx - 6, fy - 20, fx + 6, fy + 20) > 150, "the front face");
  assert.ok(count(solid, [69, 90, 100], 25) > 2000, "the shaded underside");
  await context.close();
});

test("the thread passes unrolled: a pass out of phase is a line of its own", async () => {
  const prog = join(work, "split.nc");
  // The second pass starts 0.5 mm further out on a 2 mm lead: a quarter turn out of phase.
  writeFileSync(prog, "G97 S300 M03\nG0 X30. Z5.\nG92 X28. Z-20. F2.\nG0 Z5.5\nG92 X27.5 Z-20. F2.\nG0 X40.\nM30\n");
  const { page, context, errors } = await open(report(prog, "gsk980tdi"));
  assert.deepEqual(errors, []);
  assert.equal(await page.isVisible("#passes"), true);
  const img = await shot(page, "report-passes-split.png", "#passes");
  const first = count(img, [21, 101, 192], 40), second = count(img, [216, 67, 21], 40);
  assert.ok(first > 300 && second > 300, `pass 1: ${first} px, pass 2: ${second} px`);
  await context.close();
  // O0012's four passes start in phase: they lie on each other, the last one drawn on top.
  const o = await open(report(join(root, "examples/gsk980tdi_o0012.nc"), "gsk980tdi"));
  const same = await shot(o.page, "report-passes-o0012.png", "#passes");
  const p1 = count(same, [21, 101, 192], 20, 50, 24, same.width, same.height - 44), p4 = count(same, [106, 27, 154], 20, 50, 24, same.width, same.height - 44);
  assert.ok(p4 > 300 && p1 < p4 / 10, `pass 4: ${p4} px, pass 1 showing: ${p1} px`);
  await o.context.close();
});

test("the thread: the true-scale section with the nominal M24x2 over it, dimensioned", async () => {
  const { page, context, errors } = await open(report(join(root, "examples/gsk980tdi_g71_g70_part.nc"), "gsk980tdi", ["--stock", "32x60", "--expect", "M24x2"]));
  assert.deepEqual(errors, []);
  assert.equal(await page.isVisible("#thread-section"), true);
  const img = await shot(page, "report-thread-section.png", "#thread-section");
  assert.ok(count(img, [176, 190, 197], 6) > 5000, "the metal of the section");
  assert.ok(count(img, [211, 47, 47], 40) > 100, "the nominal profile, dashed red");
  assert.match(await page.textContent("#thread"), /pitch\s*2\.000 mm/);
  // Cropped to the thread (Z0 to Z-26 on the M24x2 stud), not to the turned shank beside it.
  const [z0, z1] = await page.$eval("#thread-section", (c) => [+c.getAttribute("data-z0"), +c.getAttribute("data-z1")]);
  assert.ok(z0 >= -26 && z1 <= 0 && z1 - z0 > 7, `section from Z${z0} to Z${z1}`);
  await context.close();
});

test("a milling programme: hole markers by cycle, the views, the time by operation", async () => {
  const { page, context, errors } = await open(report(join(root, "tests/golden/fanuc0m_cycles_g17/input.nc"), "fanuc0m"));
  assert.deepEqual(errors, []);
  assert.equal(await app(page, () => window.ncsightApp.scene.h), 12);
  const img = await shot(page, "report-mill-holes.png", "#plot");
  // The G81 hole at X10 Y10: a filled marker in the G81 colour.
  const [x, y] = (await app(page, () => window.ncsightApp.toScreen(10, 10, 0))).map(Math.round);
  assert.ok(count(img, [216, 27, 96], 30, x - 6, y - 6, x + 7, y + 7) > 20, "G81 marker");
  assert.match(await page.textContent("#legend"), /G81 holes.*G84 holes/);
  for (const v of ["xz", "yz", "iso"]) {
    await page.selectOption("#view", v);
    await shot(page, `report-mill-${v}.png`, "#plot-box");
  }
  assert.match(await page.textContent("#time-by-op"), /rapid/);
  await context.close();
});

test("Chinese interface for a zh-CN browser, with a switch; GBK comments shown as written", async () => {
  const prog = join(work, "gbk.nc");
  writeFileSync(prog, Buffer.concat([
    Buffer.from("G97 S300 M03 (", "latin1"),
    Buffer.from([0xc2, 0xdd, 0xce, 0xc6, 0xb5, 0xb6]), // GBK for the Chinese word "thread tool"
    Buffer.from(")\nG0 X60. Z5.\nG92 X58. Z-20. F2.\nG0 X70.\nM30\n", "latin1"),
  ]));
  const { page, context, errors } = await open(report(prog, "gsk980tdi"), { locale: "zh-CN" });
  assert.deepEqual(errors, []);
  assert.equal(await page.textContent("#play"), "循环启动");
  // The stock simulation finds the rapid after the G92 cutting into the default bar: first, in Chinese.
  assert.match(await page.textContent("#banner"), /毛坯仿真发现 1 个问题/);
  assert.match(await page.textContent("#problems .p"), /毛坯 · crash · 行 3/);
  assert.match(await page.inputValue("#text"), /\(螺纹刀\)/);
  await shot(page, "app-zh.png");
  await page.click("#lang");
  assert.equal(await page.textContent("#play"), "CYCLE START");
  await context.close();
});

test("programme text, file names and messages cannot inject markup or script", async () => {
  const evil = [
    "(<script>window.__pwned = 1; alert(1)</script>)",
    '(<img src=x onerror="window.__pwned = 2; alert(2)">)',
    "G0 X10 Z5 (</script><script>window.__pwned = 3</script>)",
    "G0 X<b>1 Z5",
    "M30",
    "",
  ].join("\n");
  const prog = join(work, "inject.nc");
  writeFileSync(prog, evil);
  const { page, context, dialogs, errors } = await open(report(prog, "gsk980tdi"));
  const clean = async () => {
    assert.deepEqual(errors, []);
    assert.equal(await app(page, () => window.__pwned), undefined);
    assert.deepEqual(dialogs, []);
    assert.equal(await page.$$eval("img[src='x'], b", (i) => i.length), 0);
  };
  await clean();
  assert.match(await page.inputValue("#text"), /<script>window.__pwned = 1; alert\(1\)<\/script>/);
  // The comment of line 1 ends at alert(1)'s ")": the controller's alarm on the '<' after it,
  // quoting the text, as text.
  assert.match(await page.textContent("#problems"), /line 1 col 38 .*character '<'/);
  // Typed into the editor.
  const runs = await app(page, () => window.ncsightApp.runs);
  await page.fill("#text", evil.replace("M30", "(<svg onload=alert(4)>)\nM30"));
  await until(page, (n) => window.ncsightApp.runs > n, runs);
  await clean();
  // Dropped as a file whose name is markup.
  await page.evaluate((text) => {
    const dt = new DataTransfer();
    dt.items.add(new File([text], '<img src=x onerror="window.__pwned=5">.nc'));
    document.dispatchEvent(new DragEvent("drop", { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, evil);
  await until(page, () => document.getElementById("file-name").textContent.includes("onerror"));
  await clean();
  assert.match(await page.textContent("#file-name"), /<img src=x/);
  await context.close();
});

test("200,000 drilled holes: a small page, the path within 3 s, zoom and player steps under 100 ms", async () => {
  const lines = ["O1000", "G21 G17 G90 G54", "T1 M06", "S1200 M03", "G00 X0 Y0 Z50.", "G43 H1 Z50.", "G99 G81 X0 Y0 Z-5. R2. F200"];
  for (let i = 1; i < 200000; i++) lines.push(`X${((i % 500) * 2).toFixed(3)} Y${(Math.floor(i / 500) * 2).toFixed(3)}`);
  lines.push("G80", "G00 Z50.", "M30", "");
  const prog = join(work, "holes.nc");
  writeFileSync(prog, lines.join("\n"));
  const file = report(prog, "fanuc0m");
  const size = statSync(file).size;
  assert.ok(size < 8e6, `page of ${size} bytes`);
  // Measured twice and the quicker one counts: one stall of a loaded 2-core machine is not the
  // page being slow.
  const first = await open(file);
  await first.context.close();
  const { page, context, errors, shownMs } = await open(file);
  assert.deepEqual(errors, []);
  const shown = Math.min(first.shownMs, shownMs);
  console.log(`200,000 holes: page ${(size / 1e6).toFixed(2)} MB, path shown in ${shown} ms (and ${Math.max(first.shownMs, shownMs)} ms)`);
  assert.ok(shown < 3000, `path shown ${shown} ms after navigation`);
  assert.equal(await app(page, () => window.ncsightApp.scene.h), 200000);
  const steps = await stepTimes(page);
  console.log(`200,000 holes: zoom step ${steps.zoom.toFixed(1)} ms, player step ${steps.step.toFixed(1)} ms`);
  assert.ok(steps.zoom < 100, `zoom step ${steps.zoom} ms`);
  assert.ok(steps.step < 100, `player step ${steps.step} ms`);
  // The source is drawn only where it is seen, and follows the player.
  assert.ok((await page.$$eval("#overlay .o", (o) => o.length)) < 100);
  assert.equal(await page.$$eval("#overlay .o.run", (o) => o.length), 1);
  await shot(page, "holes-200k.png");
  await context.close();
});

test("1,000,000 moves: the path within 5 s, zoom and player steps under 100 ms", async () => {
  const lines = ["G21 G17 G90 G0 X0. Y0. Z5.", "G1 Z-1. F3000."];
  for (let i = 0; i < 1000000; i++) lines.push(`X${(i % 200).toFixed(1)} Y${(i / 200).toFixed(2)}`);
  lines.push("M30", "");
  const prog = join(work, "moves.nc");
  writeFileSync(prog, lines.join("\n"));
  const file = report(prog, "fanuc0m");
  const first = await open(file);
  await first.context.close();
  const { page, context, errors, shownMs } = await open(file);
  assert.deepEqual(errors, []);
  const shown = Math.min(first.shownMs, shownMs);
  console.log(`1,000,000 moves: page ${(statSync(file).size / 1e6).toFixed(2)} MB, path shown in ${shown} ms`);
  assert.ok(shown < 5000, `path shown ${shown} ms after navigation`);
  assert.equal(await app(page, () => window.ncsightApp.scene.n), 1000001);
  const steps = await stepTimes(page);
  console.log(`1,000,000 moves: zoom step ${steps.zoom.toFixed(1)} ms, player step ${steps.step.toFixed(1)} ms`);
  assert.ok(steps.zoom < 100 && steps.step < 100, `zoom step ${steps.zoom} ms, player step ${steps.step} ms`);
  await context.close();
});

/** The longest time the page's own thread did not answer, in ms, while `during` runs: a timer
 * every 10 ms notes the largest gap between its ticks. */
async function longestFreezeMs(page, during) {
  await page.evaluate(() => {
    window.__gap = 0;
    let last = performance.now();
    window.__ticker = setInterval(() => { const now = performance.now(); window.__gap = Math.max(window.__gap, now - last); last = now; }, 10);
  });
  await during();
  return page.evaluate(() => { clearInterval(window.__ticker); return window.__gap; });
}

test("the engine runs beside the page: a runaway loop never freezes it, and a new text cancels the run", async () => {
  const file = join(work, "app-worker.html");
  ncsight(["app", "-o", file]);
  const { page, context, errors } = await open(file);
  await page.selectOption("#machine", "fanuc0m");
  // A loop without end: the runaway guard stops it after many blocks (seconds of work).
  const runaway = "G21 G90 G00 X0 Y0 Z10.\n#1 = 0\nWHILE [#1 GE 0] DO 1\n#1 = #1 + 1\nEND 1\nM30\n";
  const gap = await longestFreezeMs(page, async () => {
    await page.fill("#text", runaway);
    await until(page, () => window.ncsightApp.scene && window.ncsightApp.scene.head.status === "alarm", undefined, 120000);
  });
  console.log(`# a runaway loop: the page's longest frozen interval ${Math.round(gap)} ms`);
  assert.ok(gap < 1000, `the page froze for ${Math.round(gap)} ms`);
  assert.match(await page.textContent("#problems"), /NCS-E63/);
  // Typing while a long run is under way: the run is dropped, the new text is shown.
  await page.fill("#text", runaway);
  await page.fill("#text", "G21 G90 G00 X0 Y0 Z10.\nG01 X20. F100.\nM30\n");
  await until(page, () => window.ncsightApp.scene && window.ncsightApp.scene.head.status === "ended" && window.ncsightApp.scene.n === 2);
  assert.deepEqual(errors, []);
  await context.close();
});

test("40 million holes from a 10 kB programme: the page shows the first two million records and says so, and never traps", async () => {
  const lines = ["G21 G17 G90 G00 X0 Y0 Z10."];
  for (let i = 0; i < 1000; i++) lines.push("G91 G99 G81 X0.01 Z-3. R-8. F1000. K9999");
  lines.push("G90 G80", "M30", "");
  const prog = join(work, "k9999.nc");
  writeFileSync(prog, lines.join("\n"));
  const { page, context, errors } = await open(report(prog, "fanuc0m"));
  await until(page, () => window.ncsightApp.scene && window.ncsightApp.scene.head.cut, undefined, 120000);
  const n = await page.evaluate(() => window.ncsightApp.scene.n + window.ncsightApp.scene.head.events.length);
  assert.equal(n, 2000000);
  assert.match(await page.textContent("#banner"), /shows the programme's first 2,000,000 records/);
  assert.doesNotMatch(await page.textContent("#banner"), /engine error|unreachable/);
  assert.deepEqual(errors, []);
  await context.close();
});

/** The 3D view once the engine has cut the stock for the player's time. */
async function view3d(page, name) {
  await page.selectOption("#view", "cut3d");
  await until(page, () => { const s = window.ncsightApp.stock3d(); return s && !s.busy; }, undefined, 60000);
  const s = await page.evaluate(() => window.ncsightApp.stock3d());
  return { head: s.head, note: s.note, img: await shot(page, name, "#plot-box") };
}

test("3D cut stock, lathe: the quarter section shows the drilled and bored inside, and cuts as the programme plays", async () => {
  const part = join(work, "part3d.nc");
  // Drill Ø16 (T1), bore Ø18 (T2), turn Ø38 (T3) on a Ø40 x 50 bar.
  writeFileSync(part, "G99 M03 S600\nT0101\nG00 X0. Z2.\nG01 Z-30. F0.1\nG00 Z2.\nT0202\nG00 X18. Z2.\nG01 Z-25. F0.1\nG00 X16.\nG00 Z2.\nT0303\nG00 X42. Z2.\nG01 X38. F0.2\nG01 Z-30.\nG00 X42.\nG00 X100. Z100.\nM30\n");
  const tools = join(work, "part3d.toml");
  writeFileSync(tools, '[[tool]]\nnumber = 1\nkind = "drill"\ndiameter_mm = 16.0\n[[tool]]\nnumber = 2\nkind = "boring"\n[[tool]]\nnumber = 3\nkind = "turning"\n');
  const { page, context, errors } = await open(report(part, "gsk980tdi", ["--stock", "40x50", "--setup", tools]));
  const end = await view3d(page, "cut3d-lathe.png");
  assert.deepEqual(errors, []);
  assert.equal(end.head.kind, "lathe");
  assert.deepEqual(end.head.findings, [], "the part gives no finding");
  const holed = pixels(end.img, orange);
  assert.ok(holed > 20000, `the section is drawn (${holed} orange pixels)`);
  // At the start nothing is cut: the section is the whole bar's, larger than the bored part's
  // (the bore takes Ø18 of its Ø40 over 25 mm, and the drill's cone below).
  await page.evaluate(() => window.ncsightApp.setTime(0.001));
  await until(page, () => { const s = window.ncsightApp.stock3d(); return s && !s.busy && s.head.until_s !== null; }, undefined, 60000);
  const start = pixels(await shot(page, "cut3d-lathe-start.png", "#plot-box"), orange);
  assert.ok(start > holed * 1.15, `the uncut bar's section (${start}) is larger than the bored part's (${holed})`);
  // Half way (the boring bar at work): between the two.
  await page.evaluate(() => window.ncsightApp.setTime(window.ncsightApp.scene.head.total_s * 0.45));
  await until(page, () => { const s = window.ncsightApp.stock3d(); return s && !s.busy && s.head.until_s > 1; }, undefined, 60000);
  const mid = pixels(await shot(page, "cut3d-lathe-mid.png", "#plot-box"), orange);
  assert.ok(mid < start && mid > holed * 0.9, `half way: ${mid} between ${holed} and ${start}`);
  await context.close();
});

test("3D cut stock, mill: the pocket, slot and helical bore are cut into the block; a rapid through it is marked", async () => {
  const prog = join(work, "mill3d.nc");
  writeFileSync(prog, "G21 G17 G90 G54\nT1 M06\nS3000 M03\nG00 X0 Y0 Z10.\nG00 X15. Y15.\nG01 Z-3. F100.\nG01 X29. F300.\nY19.\nX15.\nY15.\nG00 Z10.\nG00 X10. Y40.\nG01 Z-2. F100.\nG01 X50. F300.\nG00 Z10.\nG00 X70. Y20.\nG01 Z0 F100.\nG02 X70. Y20. Z-2. I-4. J0 F200.\nG02 X70. Y20. Z-4. I-4. J0\nG02 X70. Y20. Z-4. I-4. J0\nG00 Z10.\nG00 X0 Y0\nM30\n");
  const setup = join(work, "mill3d.toml");
  writeFileSync(setup, '[block]\nmin_mm = [0.0, 0.0, -20.0]\nmax_mm = [90.0, 60.0, 0.0]\n[[tool]]\nnumber = 1\nkind = "mill"\ndiameter_mm = 6.0\n');
  let { page, context, errors } = await open(report(prog, "fanuc0m", ["--setup", setup]));
  const end = await view3d(page, "cut3d-mill.png");
  assert.deepEqual(errors, []);
  assert.equal(end.head.kind, "mill");
  assert.ok(Math.abs(end.head.removed_mm3 - 1716.5) < 1716.5 * 0.05, `removed ${end.head.removed_mm3} mm³`);
  const cut = pixels(end.img, blue);
  assert.ok(cut > 1500, `the cut floors are drawn (${cut} blue pixels)`);
  assert.equal(pixels(end.img, red), 0, "no finding");
  // Before the helix (60 % of the time): less is cut.
  await page.evaluate(() => window.ncsightApp.setTime(window.ncsightApp.scene.head.total_s * 0.6));
  await until(page, () => { const s = window.ncsightApp.stock3d(); return s && !s.busy && s.head.until_s !== null; }, undefined, 60000);
  const before = pixels(await shot(page, "cut3d-mill-mid.png", "#plot-box"), blue);
  assert.ok(before < cut * 0.85, `before the helix ${before} < ${cut}`);
  await context.close();
  // A rapid through the block: a crash, marked in red where it happens.
  writeFileSync(prog, "G21 G17 G90 G54\nT1 M06\nS3000 M03\nG00 X-10. Y30. Z10.\nG00 Z-5.\nG00 X100.\nG00 Z10.\nM30\n");
  ({ page, context, errors } = await open(report(prog, "fanuc0m", ["--setup", setup])));
  const crash = await view3d(page, "cut3d-mill-crash.png");
  assert.deepEqual(crash.head.findings.map((f) => [f.kind, f.line]), [["crash", 6]]);
  assert.ok(pixels(crash.img, red) > 30, "the crash is marked");
  await context.close();
});

// ---- the page teaches: the operator's player, alarms explained, the work kept, layout, mill ----

// A textbook shaft on the GSK980TDi: G71/G70, M00, a G75 groove, a G92 thread.
const shaft = `O0001 (SHAFT)
T0101 (OD TOOL)
G99 M03 S800
G0 X42. Z2.
G71 U1.5 R0.5
G71 P10 Q20 U0.4 W0.1 F0.2
N10 G0 X26.
G1 Z0. F0.1
X30. Z-2.
Z-30.
X38.
N20 Z-45.
G70 P10 Q20
G0 X100. Z100.
M00
T0202 (GROOVE 3MM)
G0 X40. Z-30.
G75 R0.5
G75 X26. Z-30. P1500 Q0 F0.05
G0 X100. Z100.
T0303 (THREAD)
S500 M03
G0 X32. Z5.
G92 X29.2 Z-26. F2.
X28.6
X28.2
X27.9
G0 X100. Z100.
M30
`;
const stateOf = (page) => page.evaluate(() => [document.getElementById("machine-state").textContent, document.getElementById("stop-why").textContent, window.ncsightApp.now]);
const stopsOf = (page, reason) => app(page, (r) => window.ncsightApp.scene.head.events.filter((e) => e.k === "stop" && e.reason === r).map((e) => e.t), reason);

// The panel's and the screen's words (docs/reference/interface.md, third round) in each language.
const PLAYER_WORDS = {
  "zh-CN": {
    labels: ["循环启动", "进给保持", "复位", "单段", "❚❚ 暂停回放", "◀ 上一段", "下一段 ▶", "◀ 上一动作", "下一动作 ▶"],
    run: "运行", hold: "暂停", stop: "停止",
    m00: /第 15 行 M00 程序停止：按“循环启动”继续/,
    held: /螺纹中进给保持.*立即退尾，快速返回起点，停止。按“循环启动”重新车这一刀/,
    banner: /含 .*秒进给保持/,
    end: /程序结束/,
    single: /单段：第 \d+ 行程序段执行完毕/,
  },
  "en-GB": {
    labels: ["CYCLE START", "FEED HOLD", "RESET", "SINGLE BLOCK", "❚❚ Pause", "◀ Block", "Block ▶", "◀ Motion", "Motion ▶"],
    run: "RUN", hold: "HOLD", stop: "STOP",
    m00: /M00 programme stop at line 15: CYCLE START goes on/,
    held: /Thread hold .*pulled out at once, returned to the start point, stopped\. CYCLE START cuts the pass again/,
    banner: /with FEED HOLD at .* s/,
    end: /End of programme/,
    single: /Single block: the block at line \d+ is done/,
  },
};
for (const [locale, W] of Object.entries(PLAYER_WORDS))
test(`the operator's player (${locale}): stops at M00, at a FEED HOLD pressed in a G92 thread and at single-block stops; CYCLE START goes on`, async () => {
  const prog = join(work, "shaft.nc");
  writeFileSync(prog, shaft);
  const { page, context, errors } = await open(report(prog, "gsk980tdi"), { locale });
  assert.deepEqual(errors, []);
  // The panel in the controller's words, each label distinct.
  assert.deepEqual(await page.$$eval("#play, #hold, #reset, #single + span, #pause, #prev, #next, #prev-motion, #next-motion", (e) => e.map((x) => x.textContent)),
    W.labels);
  assert.equal((await stateOf(page))[0], W.stop);
  // CYCLE START from the start at 1000x: the player stops at the M00 (line 15), as the machine does.
  const [m00] = await stopsOf(page, "program_stop");
  await app(page, () => window.ncsightApp.setTime(0));
  await page.selectOption("#speed", "1000");
  await page.click("#play");
  assert.equal((await stateOf(page))[0], W.run);
  await until(page, (w) => document.getElementById("machine-state").textContent === w, W.stop);
  let [state, why, now] = await stateOf(page);
  assert.equal(now, m00);
  assert.match(why, W.m00);
  assert.equal(await app(page, () => window.ncsightApp.runLine), 15);
  // FEED HOLD pressed during the first G92 pass: played at real time there (a press can be
  // aimed), the run is made again with the press, and the player stops where the machine does:
  // pulled out at once, back at the start point. HOLD (暂停) on the screen.
  const pass = await app(page, () => { const a = window.ncsightApp; const i = [...Array(a.scene.n).keys()].find((j) => a.kindOf(j) === 3); return [a.startOf(i), a.endOf(i)]; });
  await app(page, (t) => window.ncsightApp.setTime(t + 0.05), pass[0]);
  await page.click("#play");
  await new Promise((r) => setTimeout(r, 400));
  const inThread = await app(page, () => window.ncsightApp.now);
  assert.ok(inThread > pass[0] && inThread < pass[1], `in the thread at 1x: ${inThread} s in ${pass}`);
  await page.click("#hold");
  await until(page, (w) => document.getElementById("machine-state").textContent === w, W.hold);
  [state, why, now] = await stateOf(page);
  const [held] = await stopsOf(page, "feed_hold");
  assert.equal(now, held);
  assert.match(why, W.held);
  assert.match(await page.textContent("#banner"), W.banner);
  await shot(page, `player-hold-${locale}.png`);
  // What the hold did is drawn under an amber band, seen without zooming in.
  const band = await shot(page, `player-hold-plot-${locale}.png`, "#plot");
  assert.ok(count(band, [255, 199, 115], 40) > 150, "the hold band");
  // CYCLE START: on to the end of the programme.
  await page.click("#play");
  await until(page, (w) => document.getElementById("machine-state").textContent === w, W.stop, 30000);
  [state, why, now] = await stateOf(page);
  assert.equal(now, await app(page, () => window.ncsightApp.scene.head.total_s));
  assert.match(why, W.end);
  // SINGLE BLOCK: each CYCLE START runs one block.
  await page.click("#clear-buttons");
  await page.check("#single");
  const singles = await stopsOf(page, "single_block");
  assert.ok(singles.length > 20, `${singles.length} single-block stops`);
  await app(page, () => window.ncsightApp.setTime(0));
  await page.click("#play");
  await until(page, (w) => document.getElementById("machine-state").textContent === w, W.stop);
  [state, why, now] = await stateOf(page);
  assert.equal(now, singles[0]);
  assert.match(why, W.single);
  await page.click("#play");
  await until(page, (w) => document.getElementById("machine-state").textContent === w, W.stop);
  assert.equal((await stateOf(page))[2], singles[1]);
  // Motion by motion: each pass of the G71 on its own (more motion steps than block steps).
  await app(page, () => window.ncsightApp.setTime(0));
  await page.uncheck("#single");
  let blocks = 0, motions = 0;
  await app(page, () => window.ncsightApp.setTime(0));
  while ((await app(page, () => window.ncsightApp.runLine)) <= 6 && blocks < 50) { await page.click("#next"); blocks++; }
  await app(page, () => window.ncsightApp.setTime(0));
  while ((await app(page, () => window.ncsightApp.runLine)) <= 6 && motions < 200) { await page.click("#next-motion"); motions++; }
  assert.ok(motions > blocks + 5, `${motions} motions against ${blocks} blocks up to the G71`);
  // Keys after a click: space is CYCLE START / pause, not the button clicked.
  await app(page, () => window.ncsightApp.setTime(0));
  await page.click("#next");
  const runs = await app(page, () => window.ncsightApp.runs);
  await page.keyboard.press(" ");
  assert.equal((await stateOf(page))[0], W.run);
  await page.keyboard.press(" ");
  assert.equal((await stateOf(page))[0], W.stop);
  assert.equal(await app(page, () => window.ncsightApp.runs), runs, "space ran nothing again");
  assert.deepEqual(errors, []);
  await context.close();
});

test("an alarm explained in Chinese with the controller's number (FANUC 0-T), and in English", async () => {
  const prog = join(work, "alarm.nc");
  writeFileSync(prog, "G0 X20. Z2.\nG100 Z5.\nM30\n");
  for (const [locale, re] of [["zh-CN", /PS0010 · NCS-E10 · 非法G代码 · 报警[\s\S]*常见原因[\s\S]*解决办法[\s\S]*错误示例[\s\S]*正确示例/], ["en-GB", /PS0010 · NCS-E10 · IMPROPER G-CODE · alarm[\s\S]*Usual causes[\s\S]*How to fix it[\s\S]*Wrong[\s\S]*Right/]]) {
    const { page, context, errors } = await open(report(prog, "fanuc0t"), { locale });
    assert.deepEqual(errors, []);
    await app(page, () => 0);
    assert.match(await page.textContent("#explain"), re);
    assert.match(await page.textContent("#banner"), locale === "zh-CN" ? /第 2 行：PS0010 非法G代码/ : /line 2: PS0010 IMPROPER G-CODE/);
    // Played to the end: the run stops at the alarm, ALARM on the screen.
    await app(page, () => window.ncsightApp.setTime(0));
    await page.selectOption("#speed", "1000");
    await page.click("#play");
    await until(page, () => document.getElementById("machine-state").textContent !== (document.documentElement.lang === "zh-CN" ? "运行" : "RUN"));
    assert.equal((await stateOf(page))[0], locale === "zh-CN" ? "报警" : "ALARM");
    if (locale === "zh-CN") {
      // Parameter meanings in Chinese too.
      assert.match(await page.textContent("#param-table"), /[\u4e00-\u9fff]/);
      await shot(page, "alarm-explained-zh.png");
    }
    await context.close();
  }
});

test("the work is kept: GBK saved byte for byte, an edit kept in GBK and across a reload, the plot as PNG and SVG, a setup sheet", async () => {
  const gbkComment = Buffer.from([0xcd, 0xe2, 0xd4, 0xb2, 0xb5, 0xb6]); // GBK: 外圆刀 (OD tool)
  const bytes = Buffer.concat([Buffer.from("O0002\r\nT0101 (", "latin1"), gbkComment, Buffer.from(")\r\nG99 M03 S600\r\nG0 X30. Z2.\r\nG1 Z-20. F0.2\r\nX40.\r\nG0 X100. Z100.\r\nM30\r\n", "latin1")]);
  const prog = join(work, "gbk-save.nc");
  writeFileSync(prog, bytes);
  const file = report(prog, "gsk980tdi");
  const { page, context, errors } = await open(file, { locale: "zh-CN" });
  assert.deepEqual(errors, []);
  const save = async () => {
    const [dl] = await Promise.all([page.waitForEvent("download"), page.click("#save")]);
    assert.equal(dl.suggestedFilename(), "gbk-save.nc");
    return readFileSync(await dl.path());
  };
  assert.ok((await save()).equals(bytes), "unedited: the bytes as opened");
  // Edited: the same encoding and line ends, the Chinese comment still GBK.
  const edited = (await page.inputValue("#text")).replace("F0.2", "F0.15");
  await page.fill("#text", edited);
  assert.ok((await save()).equals(Buffer.from(bytes.toString("latin1").replace("F0.2", "F0.15"), "latin1")), "edited: GBK and CR LF kept");
  // The edit is kept in the browser: a reload offers it back, and Restore puts it in the editor.
  await new Promise((r) => setTimeout(r, 1300));
  await page.reload();
  await page.evaluate(() => window.ncsightApp.ready);
  assert.ok(await page.isVisible("#restore"), "the restore bar shows");
  assert.match(await page.textContent("#restore"), /未下载的修改/);
  await page.click("#restore-yes");
  assert.equal(await page.inputValue("#text"), edited);
  await until(page, () => window.ncsightApp.scene && /F0\.15/.test(document.getElementById("text").value));
  // The plot as PNG and SVG.
  const [png] = await Promise.all([page.waitForEvent("download"), page.click("#export-png")]);
  assert.equal(readFileSync(await png.path()).subarray(1, 4).toString(), "PNG");
  const [svg] = await Promise.all([page.waitForEvent("download"), page.click("#export-svg")]);
  const svgText = readFileSync(await svg.path(), "utf8");
  assert.match(svgText, /^<svg xmlns="http:\/\/www.w3.org\/2000\/svg"/);
  assert.ok((svgText.match(/<path /g) || []).length >= 2, "rapids and the tool's cuts");
  // The setup sheet: printed alone; a row per tool with its name from its comment.
  await page.evaluate(() => { window.print = () => { window.__printed = true; }; });
  await page.click("#print-sheet");
  assert.equal(await page.evaluate(() => window.__printed), true);
  const row = await page.textContent("#sheet-tools tr:nth-child(2)");
  assert.match(row, /T01外圆刀2X Ø 30 – 40, Z -20 – 2.*mm\/min/);
  assert.match(await page.textContent("#sheet-ops"), /快速/, "the time by operation on the sheet");
  await page.emulateMedia({ media: "print" });
  await shot(page, "setup-sheet.png");
  assert.equal(await page.isVisible("#left"), false);
  await page.emulateMedia({ media: "screen" });
  assert.deepEqual(errors, []);
  await context.close();
});

test("layout at 1366 x 768 in both languages: no sideways scroll; a tall window gives the plot and editor its height", async () => {
  const prog = join(work, "shaft-layout.nc");
  writeFileSync(prog, shaft);
  const file = report(prog, "gsk980tdi");
  for (const locale of ["zh-CN", "en-GB"]) {
    const context = await browser.newContext({ viewport: { width: 1366, height: 768 }, locale });
    const page = await context.newPage();
    await page.goto("file://" + file);
    await page.evaluate(() => window.ncsightApp.ready);
    await page.evaluate(() => window.ncsightApp.settled());
    for (const id of ["passes-box", "params-box", "panel-box", "time-box"]) await page.evaluate((i) => { document.getElementById(i).open = true; }, id);
    const [scroll, width] = await page.evaluate(() => [document.documentElement.scrollWidth, document.documentElement.clientWidth]);
    assert.ok(scroll <= width, `${locale}: ${scroll} px wide in ${width}`);
    await shot(page, `layout-1366-${locale}.png`);
    const short = await page.evaluate(() => document.getElementById("plot-box").clientHeight);
    await page.setViewportSize({ width: 1366, height: 1400 });
    const tall = await page.evaluate(() => [document.getElementById("plot-box").clientHeight, document.getElementById("editor").clientHeight]);
    assert.ok(tall[0] > short + 500 && tall[1] > 900, `plot ${short} -> ${tall[0]} px, editor ${tall[1]} px`);
    await context.close();
  }
});

test("mill: tool names from the T lines' comments, the tool-change time, every cycle at a hole, the iso view's block and axes", async () => {
  const prog = join(work, "mill-ops.nc");
  writeFileSync(prog, `O0003 (THREE OPERATIONS ON THE SAME HOLES)
G21 G17 G40 G49 G80 G90
T1 M06 (SPOT DRILL D10)
G0 X0. Y0. Z50. S1500 M03
G99 G81 X20. Y20. Z-2. R3. F100.
X60.
G80
T2 M06 (DRILL D8.5)
S1000 M03
G99 G83 X20. Y20. Z-25. R3. Q5. F120.
X60.
G80
T3 M06 (TAP M10X1.5)
S400 M03
G99 G84 X20. Y20. Z-20. R5. F600.
X60.
G80
G0 Z100.
M30
`);
  const { page, context, errors } = await open(report(prog, "fanuc0m", ["--param", "tool_change_s=6"]));
  assert.deepEqual(errors, []);
  assert.match(await page.textContent("#legend"), /T01 SPOT DRILL D10.*T02 DRILL D8\.5.*T03 TAP M10X1\.5/);
  assert.match(await page.textContent("#time-by-op"), /tool changes \(3 × 6 s\)0:18\.0/);
  // Each operation's marker at the hole X20 Y20: G81, G83 and G84 colours all there.
  const img = await shot(page, "mill-three-operations.png", "#plot");
  const [x, y] = (await app(page, () => window.ncsightApp.toScreen(20, 20, 0))).map(Math.round);
  for (const [name, colour] of [["G81", [216, 27, 96]], ["G83", [0, 137, 123]], ["G84", [244, 81, 30]]]) assert.ok(count(img, colour, 30, x - 16, y - 16, x + 17, y + 17) > 8, `${name} marker at the hole`);
  // The peck hole is marked at its bottom (Z-25), not at its first peck.
  assert.ok(await app(page, () => window.ncsightApp.holeDepths().includes(-25)));
  // The iso view: the stock block (guessed from the cuts, dashed) and the axis triad.
  await page.selectOption("#view", "iso");
  const iso = await shot(page, "mill-iso-block-triad.png", "#plot");
  const h = iso.height;
  assert.ok(count(iso, [198, 40, 40], 30, 0, h - 90, 90, h) > 20 && count(iso, [46, 125, 50], 30, 0, h - 90, 90, h) > 20 && count(iso, [21, 101, 192], 30, 0, h - 90, 90, h) > 20, "X, Y, Z arrows");
  assert.ok(count(iso, [141, 110, 99], 30, 0, 0, iso.width, h) > 100, "the block's edges");
  assert.match(await page.textContent("#legend"), /G81 holes.*G83 holes.*G84 holes/);
  assert.deepEqual(errors, []);
  await context.close();
});

test("a first line (ncsight: fanuc0m) chooses the controller in the page, as on the command line", async () => {
  const file = join(work, "app-named.html");
  ncsight(["app", "-o", file]);
  const { page, context, errors } = await open(file);
  await page.selectOption("#machine", "gsk980tdi");
  await page.fill("#text", "(ncsight: fanuc0m)\nG0 X0. Y0. Z50.\nG99 G81 X20. Y20. Z-5. R3. F100.\nG80\nM30\n");
  await until(page, () => window.ncsightApp.scene && window.ncsightApp.scene.h === 1);
  assert.equal(await page.inputValue("#machine"), "fanuc0m");
  assert.match(await page.textContent("#banner"), /No problems/);
  // Chosen by hand afterwards, the choice stays while the first line does not change.
  await page.selectOption("#machine", "fanuc0i-mf");
  await page.fill("#text", "(ncsight: fanuc0m)\nG0 X0. Y0. Z50.\nG99 G81 X30. Y20. Z-5. R3. F100.\nG80\nM30\n");
  await until(page, () => window.ncsightApp.scene && window.ncsightApp.scene.head.machine === "fanuc0i-mf");
  assert.deepEqual(errors, []);
  await context.close();
});

test("port to another controller in the page: the two programmes side by side, the ported path overlaid, the differences listed", async () => {
  const { page, context, errors } = await open(report(join(root, "examples/gsk980tdi_o0012.nc"), "gsk980tdi"), { locale: "zh-CN" });
  assert.deepEqual(errors, []);
  await page.click("#port-box summary");
  await page.selectOption("#port-to", "fanuc0t");
  await page.click("#port-run");
  await until(page, () => document.getElementById("port-text").textContent.length > 0);
  assert.match(await page.textContent("#port-status"), /在 fanuc0t 上运动相同，已运行两者验证/);
  assert.match(await page.textContent("#port-text"), /^O0012; \(ncsight: fanuc0t\)/);
  assert.equal(await page.textContent("#port-from"), await page.inputValue("#text"));
  // The ported path under the original's: an orange band on the plot.
  const img = await shot(page, "port-overlay.png", "#plot");
  assert.ok(count(img, [255, 190, 128], 40) > 200, "the ported path's band");
  await shot(page, "port-side-by-side.png");
  // The download is the ported programme.
  const [dl] = await Promise.all([page.waitForEvent("download"), page.click("#port-save")]);
  assert.equal(dl.suggestedFilename(), "gsk980tdi_o0012-fanuc0t.nc");
  assert.match(readFileSync(await dl.path(), "utf8"), /^O0012; \(ncsight: fanuc0t\)/);
  // What cannot be the same is listed: the GSK988T's arc thread on the FANUC 0-T.
  await page.selectOption("#machine", "gsk988t");
  await page.fill("#text", readFileSync(join(root, "tests/golden/seed002_arc_thread/input.nc"), "utf8"));
  await until(page, () => window.ncsightApp.scene && window.ncsightApp.scene.head.machine === "gsk988t");
  await page.selectOption("#port-to", "fanuc0t");
  await page.click("#port-run");
  await until(page, () => /近似/.test(document.getElementById("port-status").textContent));
  assert.ok((await page.$$("#port-list .p.alarm")).length > 0, "differences listed");
  assert.deepEqual(errors, []);
  await context.close();
});
