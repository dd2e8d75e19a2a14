"use strict";
// The ncsight page: the engine (the core in WebAssembly, inline below as base64) runs the
// programme in the editor on the controller chosen, and the page draws, plays and measures the
// run. Programme text, file names and messages only ever reach the document as text
// (textContent, a textarea's value, canvas text), never as markup.
(function () {
  const $ = (id) => document.getElementById(id);
  const el = (tag, attrs, text) => {
    const e = document.createElement(tag);
    for (const k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = String(text);
    return e;
  };
  // The engine compiles (off the main thread) while the job is read.
  const compiled = compileEngine();
  compiled.catch(() => {}); // reported where it is awaited
  const JOB = JSON.parse($("ncsight-job").textContent);
  const LH = 18; // editor line height, px

  // ---- words of the interface: English and Chinese ----------------------------------------
  // Each word as [English, Chinese].
  const WORDS = {
    machine: ["Controller", "控制器"],
    stock: ["Stock", "毛坯"],
    open: ["Open…", "打开…"],
    source: ["Programme", "程序"],
    auto: ["run as I type", "输入即运行"],
    run: ["Run", "运行"],
    fit: ["Fit", "适应窗口"],
    play: ["CYCLE START", "循环启动"],
    pause: ["❚❚ Pause", "❚❚ 暂停回放"],
    prev: ["◀ Block", "◀ 上一段"],
    next: ["Block ▶", "下一段 ▶"],
    prevm: ["◀ Motion", "◀ 上一动作"],
    nextm: ["Motion ▶", "下一动作 ▶"],
    nexttool: ["Next tool", "下一把刀"],
    tocursor: ["Run to cursor", "运行到光标"],
    slow: ["threads at real time", "螺纹处按实际速度"],
    speed: ["Speed", "速度"],
    panel: ["Operator panel", "操作面板"],
    hold: ["FEED HOLD", "进给保持"],
    reset: ["RESET", "复位"],
    clear: ["Clear presses", "清除按键"],
    single: ["SINGLE BLOCK", "单段"],
    dry: ["Dry run", "空运行"],
    bdel: ["Block delete", "程序段跳过"],
    opt: ["Optional stop (M01)", "选择停 (M01)"],
    ms_run: ["RUN", "运行"],
    ms_hold: ["HOLD", "暂停"],
    ms_stop: ["STOP", "停止"],
    ms_alarm: ["ALARM", "报警"],
    why_paused: ["The player is paused (the machine would go on): CYCLE START or space plays on.", "回放已暂停（机床并未停止）：按“循环启动”或空格继续。"],
    why_m00: ["M00 programme stop at line {line}: CYCLE START goes on.", "第 {line} 行 M00 程序停止：按“循环启动”继续。"],
    why_m01: ["M01 optional stop at line {line} (optional stop on): CYCLE START goes on.", "第 {line} 行 M01 选择停（选择停开关已开）：按“循环启动”继续。"],
    why_g88: ["G88 at line {line}: the operator retracts the tool by hand, then CYCLE START.", "第 {line} 行 G88：操作者手动退刀后按“循环启动”。"],
    why_single: ["Single block: the block at line {line} is done; CYCLE START runs the next.", "单段：第 {line} 行程序段执行完毕；按“循环启动”执行下一段。"],
    why_reset: ["RESET: the axes stopped and the programme ended.", "复位：各轴停止，程序结束。"],
    why_stop: ["Stopped at line {line}.", "在第 {line} 行停止。"],
    why_end: ["End of programme.", "程序结束。"],
    why_textend: ["The text ended without M30 or M02.", "程序文本已完，没有 M30 或 M02。"],
    why_alarm: ["Alarm at line {line}: {code} {title}. The run stops here, as the controller does.", "第 {line} 行报警：{code} {title}。运行在此停止，与系统相同。"],
    why_hold: ["FEED HOLD at {t}: the axes decelerated to a stop; CYCLE START goes on.", "{t} 进给保持：各轴减速停止；按“循环启动”继续。"],
    why_hold_end: ["FEED HOLD at {t}: the machine stopped where this block lets it (a tapping or thread block goes on to its end); CYCLE START goes on.", "{t} 进给保持：机床在本段允许处停止（攻丝、螺纹段执行到底才停）；按“循环启动”继续。"],
    why_hold_thread: ["Thread hold (FEED HOLD at {t}): {pulled}{back}stopped. CYCLE START cuts the pass again.", "螺纹中进给保持（{t}）：{pulled}{back}停止。按“循环启动”重新车这一刀。"],
    why_hold_thread_finish: ["Thread hold (FEED HOLD at {t}): the pass went on to its end and its pull-out, {back}stopped. CYCLE START goes on.", "螺纹中进给保持（{t}）：本刀车到终点并退尾，{back}停止。按“循环启动”继续。"],
    why_pulled: ["pulled out at once, ", "立即退尾，"],
    why_back: ["returned to the start point, ", "快速返回起点，"],
    withholds: ["with {list}", "含 {list}"],
    feedov: ["Feed override", "进给倍率"],
    rapidov: ["Rapid override", "快速倍率"],
    params: ["Parameters (N=V or N.B=V, one a line)", "参数（N=V 或 N.B=V，每行一个）"],
    time: ["Time", "时间"],
    thread: ["Thread form (ncsight report)", "螺纹牙形（ncsight report）"],
    paramtable: ["Parameters and assumptions", "参数与假设"],
    lang: ["中文", "English"],
    rapid: ["rapid", "快速"],
    pullout: ["pull-out", "退尾"],
    tool: ["T", "T"],
    ok: ["No problems: {status} at {time}", "没有问题：{status}，用时 {time}"],
    problems: ["{alarms} alarm(s), {warnings} warning(s)", "{alarms} 个报警，{warnings} 个警告"],
    first: ["first: line {line}: {msg}", "第一个：第 {line} 行：{msg}"],
    ended: ["ended", "程序结束"],
    stopped: ["stopped", "停止"],
    alarm: ["alarm", "报警"],
    warningk: ["warning", "警告"],
    ex_causes: ["Usual causes", "常见原因"],
    port_title: ["Port to another controller", "移植到其他系统"],
    port_to: ["To", "目标"],
    port_run: ["Port", "移植"],
    port_overlay: ["overlay the ported path", "叠加移植后的路径"],
    port_download: ["Download ported", "下载移植程序"],
    port_from: ["as written", "原程序"],
    port_result: ["ported", "移植后"],
    port_exact: ["The same motion on {to}, verified by running both ({n} line(s) written as their moves)", "在 {to} 上运动相同，已运行两者验证（{n} 行改写为直接运动）"],
    port_approx: ["Approximate on {to}: {d} difference(s) ({n} line(s) written as their moves)", "在 {to} 上近似：{d} 处不同（{n} 行改写为直接运动）"],
    port_alarm: ["The programme alarms on {from} (line {line}): nothing to port", "程序在 {from} 上报警（第 {line} 行）：无法移植"],
    port_rewritten: ["line {line} written as its moves: {why}", "第 {line} 行改写为直接运动：{why}"],
    port_diff: ["difference at line {line}: {what} ({size})", "第 {line} 行不同：{what}（{size}）"],
    save: ["Download", "下载程序"],
    png: ["PNG", "PNG"],
    svg: ["SVG", "SVG"],
    export_title: ["the plot as an image", "导出图形"],
    sheet: ["Setup sheet", "调整单"],
    restore_yes: ["Restore", "恢复"],
    restore_no: ["Discard", "丢弃"],
    restore: ["Edits of {file} not downloaded, kept in this browser at {at}:", "{file} 未下载的修改已保存在此浏览器（{at}）："],
    newfile: ["the new programme", "新程序"],
    gbk_missing: ["Downloaded in GBK, as opened; {n} character(s) GBK lacks are written as ?", "已按打开时的 GBK 编码下载；{n} 个 GBK 没有的字符写成了 ?"],
    sh_tool: ["Tool", "刀具"],
    sh_name: ["Name (its comment)", "名称（注释）"],
    sh_xz: ["Cutting extents (mm)", "切削范围 (mm)"],
    sh_xyz: ["Cutting extents (mm)", "切削范围 (mm)"],
    sh_feed: ["Feeds", "进给"],
    sh_speed: ["Spindle", "主轴转速"],
    sh_cut: ["Cutting", "切削时间"],
    sheet_note: ["Times as ncsight runs the programme on this controller (tool changes, spindle waits and stops are in the total). Extents are of the cutting moves, X as a diameter on a lathe.", "时间为 ncsight 按此控制器运行程序所得（换刀、主轴等待和停止计入合计）。范围为切削移动的范围，车床 X 为直径。"],
    ex_fix: ["How to fix it", "解决办法"],
    ex_wrong: ["Wrong", "错误示例"],
    ex_right: ["Right", "正确示例"],
    running: ["running…", "运行中…"],
    usage: ["Cannot run: {msg}", "无法运行：{msg}"],
    total: ["Total", "合计"],
    bytool: ["By tool", "按刀具"],
    byop: ["By operation", "按动作"],
    feedk: ["feed", "切削进给"],
    arc: ["arc", "圆弧"],
    threadk: ["thread", "螺纹"],
    dwell: ["dwell", "暂停"],
    turn: ["rotary turn", "回转轴"],
    waits: ["spindle, tool change, stops", "主轴、换刀、停止"],
    toolchanges: ["tool changes ({n} × {s} s)", "换刀（{n} × {s} 秒）"],
    line: ["line", "行"],
    col: ["col", "列"],
    state_t: ["t", "时间"],
    state_line: ["line", "行"],
    spindle: ["spindle", "主轴"],
    angle: ["angle", "角度"],
    lead: ["lead", "导程"],
    feedrate: ["feed", "进给"],
    empty: ["Paste a programme, drop a file here, or open one.", "粘贴程序、把文件拖到这里，或打开文件。"],
    presses: ["presses: {list}", "按键：{list}"],
    holdat: ["FEED HOLD at {t} s", "{t} 秒进给保持"],
    resetat: ["RESET at {t} s", "{t} 秒复位"],
    more: ["{n} more not listed", "另有 {n} 条未列出"],
    hole: ["holes", "孔"],
    view_lathe: ["Z–X (lathe)", "Z–X（车床）"],
    view_xy: ["top X–Y", "俯视 X–Y"],
    view_xz: ["front X–Z", "正视 X–Z"],
    view_yz: ["side Y–Z", "侧视 Y–Z"],
    view_iso: ["3D (isometric)", "三维（等轴测）"],
    view_part3d: ["3D part", "三维工件"],
    view_cut3d: ["3D cut stock (WebGL)", "三维切削毛坯 (WebGL)"],
    gl_none: ["The 3D view needs WebGL, which this browser does not offer", "三维视图需要 WebGL，此浏览器不支持"],
    gl_wait: ["cutting the stock…", "正在切削毛坯…"],
    work_zero: ["work zero", "工件零点"],
    block: ["stock {x} × {y} × {z}", "毛坯 {x} × {y} × {z}"],
    blockguess: ["stock guessed from the cuts {x} × {y} × {z} (type XxYxZ in Stock to set)", "按切削估计的毛坯 {x} × {y} × {z}（在“毛坯”中输入 XxYxZ 设定）"],
    stockguess: ["stock from the programme (type DIAxLEN to set)", "按程序估计的毛坯（输入 直径x长度 设定）"],
    part: ["part", "工件"],
    notrun: ["Not run: the text is larger than auto-run allows; press Run.", "未运行：程序太大，不自动运行；请按“运行”。"],
    cut: ["The page shows the programme's first {n} records; it goes on beyond them (ncsight run on the command line runs all of it).", "页面只显示程序的前 {n} 条记录，程序在此之后还有（用命令行 ncsight run 可运行全部）。"],
    passes: ["Thread passes, unrolled", "螺纹走刀展开图"],
    passes_axis: ["spindle angle at the tool's point, down; each pass in its colour (a pass out of phase shows as its own line)", "纵向为刀尖处的主轴角度；每刀一种颜色（相位不对的一刀自成一条线）"],
    pass: ["pass {n}", "第 {n} 刀"],
    section: ["Axial section at 0°, true scale", "0° 轴向剖面，真实比例"],
    nominal: ["dashed: nominal", "虚线：名义牙形"],
    unrolled: ["Unrolled surface: Z across, angle down, darker is deeper", "展开表面：横向 Z，纵向角度，越深越暗"],
    p_param: ["parameter", "参数"],
    p_value: ["value", "值"],
    p_unit: ["unit", "单位"],
    p_meaning: ["meaning", "含义"],
    p_source: ["source", "来源"],
    stockfinding: ["stock", "毛坯"],
    findings: ["{n} finding(s) of the stock simulation", "毛坯仿真发现 {n} 个问题"],
    simerror: ["The thread could not be simulated on the stock", "无法在毛坯上仿真螺纹"],
    notsim: ["Not simulated", "未仿真"],
    edit: ["Edit (slow for a programme this long)", "编辑（程序很长，会较慢）"],
    bycheck: ["(found by the check; the run stopped before)", "（检查发现；运行在此之前已停止）"],
    bycheck_ended: ["(found by the check)", "（检查发现）"],
    seconds: ["s", "秒"],
    of: ["of", "/"],
    block: ["block", "段"],
    kinds: [["rapid","feed","arc","thread","thread arc"], ["快速","直线","圆弧","螺纹","圆弧螺纹"]],
    threadtitle: ["Computed by ncsight report for the programme as it was written (not re-run on edit).", "由 ncsight report 按原程序计算（编辑后不重算）。"],
  };
  let lang = (JOB.lang || (navigator.languages || [navigator.language || "en"]).find((l) => /^(zh|en)/i.test(l)) || "en").toLowerCase().startsWith("zh") ? "zh" : "en";
  const t = (key, vars) => {
    const w = WORDS[key];
    let s = w === undefined ? key : w[lang === "zh" ? 1 : 0];
    for (const k in vars || {}) s = s.split("{" + k + "}").join(String(vars[k]));
    return s;
  };
  function applyWords() {
    document.documentElement.lang = lang === "zh" ? "zh-CN" : "en";
    document.querySelectorAll("[data-i18n]").forEach((e) => { e.textContent = t(e.getAttribute("data-i18n")); });
    $("lang").textContent = t("lang");
    setMachineState(machineState, stopWhy);
    fillViews();
  }

  // ---- the engine -------------------------------------------------------------------------
  const enc = new TextEncoder();
  function compileEngine() {
    try {
      const b64 = $("ncsight-engine").textContent.trim();
      if (!b64) throw new Error("this page was written without its engine");
      const bin = atob(b64);
      const bytes = new Uint8Array(bin.length);
      for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
      return WebAssembly.compile(bytes);
    } catch (e) {
      return Promise.reject(e);
    }
  }
  /** The engine runs in a Web Worker of its own, so the page stays responsive however long a
   * run takes; a newer run ends the one in flight (the worker is stopped and a new one started).
   * The worker is made from this function's text (a blob: URL, allowed by the page's policy). */
  function engineWorker() {
    let E = null;
    self.onmessage = async (m) => {
      const { id, module, name, bufs } = m.data;
      try {
        if (!E) E = (await WebAssembly.instantiate(module, {})).exports;
        // Pointers come back as signed 32-bit numbers: >>> 0 reads those above 2 GB right.
        const ptrs = bufs.map((b) => { const p = E.ncsight_alloc(b.length) >>> 0; new Uint8Array(E.memory.buffer, p, b.length).set(b); return p; });
        const args = [];
        ptrs.forEach((p, i) => args.push(p, bufs[i].length));
        const at = E[name](...args) >>> 0;
        const len = new DataView(E.memory.buffer).getUint32(at, true);
        // A copy: the columns' typed arrays need offsets aligned from the buffer's start.
        const out = E.memory.buffer.slice(at + 4, at + 4 + len);
        E.ncsight_free(at, 4 + len);
        ptrs.forEach((p, i) => E.ncsight_free(p, bufs[i].length));
        self.postMessage({ id, out }, [out]);
      } catch (e) {
        // A trap: the instance's memory is not to be trusted any more; the next call makes a new one.
        E = null;
        self.postMessage({ id, error: String((e && e.message) || e) });
      }
    };
  }
  const CANCELLED = new Error("cancelled by a newer run");
  let worker = null, nextCall = 0;
  const pending = new Map();
  function startWorker() {
    const url = URL.createObjectURL(new Blob(["(" + engineWorker.toString() + ")()"], { type: "text/javascript" }));
    worker = new Worker(url);
    URL.revokeObjectURL(url);
    worker.onmessage = (m) => {
      const call = pending.get(m.data.id);
      if (!call) return;
      pending.delete(m.data.id);
      if (m.data.error !== undefined) call.reject(new Error(m.data.error)); else call.resolve(m.data.out);
    };
    worker.onerror = (e) => { const calls = [...pending.values()]; pending.clear(); stopWorker(); calls.forEach((c) => c.reject(new Error(e.message || "the engine's worker failed"))); };
  }
  function stopWorker() { if (worker) worker.terminate(); worker = null; }
  /** A run still in flight is ended (its answer would be for an older text). */
  function cancelEngine() {
    if (!pending.size) return;
    stopWorker();
    const calls = [...pending.values()];
    pending.clear();
    calls.forEach((c) => c.reject(CANCELLED));
  }
  /** The files where called programmes are looked for, as the engine takes them: a u32 length
   * and the name, a u32 length and the text, for each. */
  let libraryCache = null;
  function libraryBytes() {
    if (libraryCache) return libraryCache;
    const parts = [];
    (JOB.library || []).forEach(([name, text]) => [enc.encode(name), enc.encode(text)].forEach((b) => { const l = new Uint8Array(4); new DataView(l.buffer).setUint32(0, b.length, true); parts.push(l, b); }));
    const out = new Uint8Array(parts.reduce((a, b) => a + b.length, 0));
    let at = 0;
    parts.forEach((b) => { out.set(b, at); at += b.length; });
    return (libraryCache = out);
  }
  /** Call the engine's `ncsight_scene` or `ncsight_check` (same arguments) in the worker: a
   * promise of its answer's bytes. */
  async function callEngine(name, textBytes, machine, params, setup, options) {
    const module = await compiled;
    if (!worker) startWorker();
    const bufs = [textBytes, enc.encode(machine), enc.encode(params), enc.encode(setup), enc.encode(options), libraryBytes()];
    const id = ++nextCall;
    return new Promise((resolve, reject) => {
      pending.set(id, { resolve, reject });
      worker.postMessage({ id, module, name, bufs });
    });
  }
  /** The scene's header and columns as typed arrays (see ncsight-io's format/scene.rs). */
  function parseScene(buf) {
    const u8 = new Uint8Array(buf);
    const magic = String.fromCharCode(u8[0], u8[1], u8[2], u8[3]);
    if (magic === "NCSE") return { usage: new TextDecoder().decode(u8.subarray(4)) };
    const jl = new DataView(buf).getUint32(4, true);
    const head = JSON.parse(new TextDecoder().decode(u8.subarray(8, 8 + jl)));
    const n = head.segments, h = head.holes;
    let at = Math.ceil((8 + jl) / 8) * 8;
    const take = (Type, count) => { const a = new Type(buf, at, count); at += count * Type.BYTES_PER_ELEMENT; return a; };
    const S = { head, n, h };
    S.t = take(Float64Array, n); S.p = take(Float32Array, 6 * n); S.arc = take(Float32Array, 4 * n); S.rate = take(Float32Array, n);
    S.line = take(Uint32Array, n); S.tool = take(Uint16Array, n); S.kind = take(Uint8Array, n);
    at = Math.ceil(at / 4) * 4;
    S.holeAt = take(Float32Array, 3 * h); S.holeSeg = take(Uint32Array, h); S.holeKind = take(Uint8Array, h);
    // When each motion starts: after the record before it (a dwell, a spindle wait, a tool change).
    S.t0 = new Float64Array(n);
    let e = 0;
    const ev = head.events;
    for (let i = 0; i < n; i++) {
      let s = i ? S.t[i - 1] : 0;
      while (e < ev.length && ev[e].seg <= i) { if (ev[e].seg === i) s = Math.max(s, ev[e].t); e++; }
      S.t0[i] = Math.min(s, S.t[i]);
    }
    // Where single block stops: motions and other records that end a block.
    const ends = [];
    for (let i = 0; i < n; i++) if (S.kind[i] & 64) ends.push(S.t[i]);
    ev.forEach((x) => { if (x.be) ends.push(x.t); });
    S.blockEnds = Float64Array.from(ends).sort();
    S.tools = [];
    ev.forEach((x) => { if (x.k === "tool" && !S.tools.includes(x.tool)) S.tools.push(x.tool); });
    // Each motion's drawing style: 0 rapid, 1 pull-out, then per tool (in order of appearance)
    // 2 + 2t a cut, 3 + 2t a thread.
    const toolIndex = new Map(S.tools.map((x, j) => [x, j]));
    S.style = new Uint16Array(n);
    for (let i = 0; i < n; i++) {
      const k = S.kind[i] & 7;
      const ti = toolIndex.has(S.tool[i]) ? toolIndex.get(S.tool[i]) + 1 : 0;
      S.style[i] = k === 0 ? 0 : S.kind[i] & 32 ? 1 : (k >= 3 ? 3 : 2) + 2 * ti;
    }
    S.threadOf = new Map(head.threads.map((r) => [r[0], r]));
    // The other records before each motion (dwells, spindle, tools, stops), by that motion.
    S.eventsBefore = new Map();
    ev.forEach((x) => { if (!S.eventsBefore.has(x.seg)) S.eventsBefore.set(x.seg, []); S.eventsBefore.get(x.seg).push(x); });
    return S;
  }

  // ---- state --------------------------------------------------------------------------------
  let S = null; // the scene
  let now = 0;
  let selLine = 0;
  let runLine = 0;
  let timer = 0;
  const presses = { holds: [], reset: null };
  let lathe = true;
  let fitted = true;
  let fresh = true; // the next run is of a new programme
  let fileName = JOB.file || "";
  const view = { s: 1, ou: 0, ov: 0, kind: "lathe" };
  const VIEWS = {
    lathe: { pu: [0, 0, 1], pv: [1, 0, 0], names: ["Z", "X Ø"] },
    // The turned part as a solid, seen from the side turned 25 degrees towards the spindle's end
    // (the axis at 65 degrees to the line of sight).
    part3d: { pu: [0, 0.4226, 0.9063], pv: [1, 0, 0], names: ["", ""], solid: true },
    xy: { pu: [1, 0, 0], pv: [0, 1, 0], names: ["X", "Y"] },
    xz: { pu: [1, 0, 0], pv: [0, 0, 1], names: ["X", "Z"] },
    yz: { pu: [0, 1, 0], pv: [0, 0, 1], names: ["Y", "Z"] },
    iso: { pu: [0.7071, -0.7071, 0], pv: [-0.4082, -0.4082, 0.8165], names: ["", ""] },
  };
  const PALETTE = ["#1565c0", "#2e7d32", "#c62828", "#6a1b9a", "#ef6c00", "#00838f", "#ad1457", "#4e342e", "#283593", "#558b2f"];
  const HOLE_COLOURS = ["#d81b60", "#00897b", "#f4511e", "#3949ab", "#7cb342", "#8e24aa", "#fb8c00", "#00acc1"];
  const toolColour = (tool) => { const i = S ? S.tools.indexOf(tool) : -1; return i < 0 ? "#37474f" : PALETTE[i % PALETTE.length]; };

  // ---- machines, views, panel ---------------------------------------------------------------
  JOB.machines.forEach((m) => $("machine").appendChild(el("option", { value: m[0] }, m[0] + " — " + m[1])));
  $("machine").value = JOB.machine || "gsk980tdi";
  for (let f = 200; f >= 10; f -= 10) $("feed-ov").appendChild(el("option", { value: f }, f + " %"));
  $("feed-ov").value = "100";
  function fillViews() {
    const sel = $("view");
    const keep = sel.value;
    while (sel.firstChild) sel.removeChild(sel.firstChild);
    (lathe ? ["lathe", "part3d", "cut3d"] : ["xy", "xz", "yz", "iso", "cut3d"]).forEach((k) => sel.appendChild(el("option", { value: k }, t("view_" + k))));
    sel.value = [...sel.options].some((o) => o.value === keep) ? keep : sel.options[0].value;
    view.kind = sel.value;
  }
  $("stock").value = JOB.stock ? JOB.stock.diameter_mm + "x" + JOB.stock.length_mm : "";
  $("params").value = (JOB.params || []).join("\n");
  $("single").checked = !!(JOB.options && JOB.options.single_block);
  $("dry").checked = !!(JOB.options && JOB.options.dry_run);
  $("bdel").checked = !!(JOB.options && JOB.options.block_delete);
  $("opt").checked = !!(JOB.options && JOB.options.optional_stop);
  if (JOB.options) {
    // A value the lists lack (--feed-override 105) is added to them.
    [["feed-ov", JOB.options.feed_override || 100, " %"], ["rapid-ov", JOB.options.rapid_override || 100, ""]].forEach(([id, v, unit]) => {
      if (![...$(id).options].some((o) => o.value === String(v))) $(id).appendChild(el("option", { value: String(v) }, v + unit));
      $(id).value = String(v);
    });
    presses.holds = (JOB.options.feed_hold_at || []).slice();
    presses.reset = JOB.options.reset_at === undefined ? null : JOB.options.reset_at;
  }
  $("file-name").textContent = fileName;

  // ---- the editor: a textarea over a highlight layer, with a gutter; only visible rows drawn --
  const ta = $("text");
  const viewer = $("viewer");
  // A programme of more lines than a textarea lays out quickly is shown read-only, only the rows
  // in view drawn; "Edit" puts it into the textarea all the same.
  const BIG_LINES = 20000;
  let big = null; // { text, lines } while shown read-only
  let lineCount = 1;
  let diagByLine = new Map();
  function lineCountOf(text) { let c = 1; for (let i = text.indexOf("\n"); i >= 0; i = text.indexOf("\n", i + 1)) c++; return c; }
  /** Where line `n` (1-based) of `text` starts, or -1 past its end. */
  function lineStart(text, n) {
    let at = 0;
    for (let k = 1; k < n && at >= 0; k++) { const nl = text.indexOf("\n", at); at = nl < 0 ? -1 : nl + 1; }
    return at;
  }
  function setProgramme(text, forceEdit) {
    const c = lineCountOf(text);
    if (c > BIG_LINES && !forceEdit) {
      big = { text, lines: text.split("\n") };
      ta.value = ""; ta.hidden = true; viewer.hidden = false; $("edit").hidden = false;
      $("spacer").style.height = c * LH + "px";
      viewer.scrollTop = 0;
    } else {
      big = null;
      ta.value = text; ta.hidden = false; viewer.hidden = true; $("edit").hidden = true;
      ta.scrollTop = 0;
    }
    lineCount = c;
  }
  const programmeText = () => (big ? big.text : ta.value);
  /** The text of line `n` (1-based). */
  function sourceLine(n) {
    if (big) return big.lines[n - 1] || "";
    const s = ta.value, at = lineStart(s, n);
    if (at < 0) return "";
    const end = s.indexOf("\n", at);
    return s.slice(at, end < 0 ? s.length : end);
  }
  const scroller = () => (big ? viewer : ta);
  setProgramme(JOB.text || "");
  const countLines = () => { lineCount = lineCountOf(ta.value); };
  let editorHeight = 0;
  function paintEditor() {
    const sc = scroller();
    const top = sc.scrollTop, hgt = editorHeight || (editorHeight = $("code").clientHeight || 500);
    const first = Math.max(0, Math.floor(top / LH) - 2), last = Math.min(lineCount, Math.ceil((top + hgt) / LH) + 2);
    const gut = $("gutter-rows"), ov = $("overlay");
    gut.textContent = ""; ov.textContent = "";
    const gf = document.createDocumentFragment(), of = document.createDocumentFragment();
    for (let i = first; i < last; i++) {
      const n = i + 1, y = i * LH - top + "px";
      const sev = diagByLine.get(n);
      const g = el("div", { class: "g" + (sev ? " " + sev : "") + (n === runLine ? " run" : ""), "data-line": n }, n);
      g.style.top = y;
      gf.appendChild(g);
      const cls = n === runLine ? "run" : n === selLine ? "sel" : sev || "";
      if (cls || big) {
        const o = el("div", { class: "o " + cls + (big ? " txt" : ""), "data-line": n }, big ? big.lines[i] : undefined);
        o.style.top = y;
        of.appendChild(o);
      }
    }
    gut.appendChild(gf); ov.appendChild(of);
  }
  viewer.addEventListener("scroll", paintEditor);
  viewer.addEventListener("click", (e) => { const r = viewer.getBoundingClientRect(); select(Math.min(lineCount, Math.floor((e.clientY - r.top + viewer.scrollTop) / LH) + 1), false); });
  $("edit").addEventListener("click", () => { const top = viewer.scrollTop; setProgramme(big.text, true); ta.scrollTop = top; paintEditor(); });
  ta.addEventListener("scroll", paintEditor);
  function caretLine() { if (big) return selLine || 1; const s = ta.value; let n = 1; const end = ta.selectionStart; for (let i = s.indexOf("\n"); i >= 0 && i < end; i = s.indexOf("\n", i + 1)) n++; return n; }
  function showLine(n, moveCaret) {
    const sc = scroller(), top = (n - 1) * LH, h = editorHeight || 500;
    if (top < sc.scrollTop || top + LH > sc.scrollTop + h) sc.scrollTop = Math.max(0, top - h / 3);
    if (moveCaret && !big) {
      const at = lineStart(ta.value, n);
      if (at >= 0) ta.setSelectionRange(at, at);
    }
    paintEditor();
  }
  ta.addEventListener("click", () => { selLine = caretLine(); paintEditor(); draw(); });
  /** The machine a programme names on its first line, `(ncsight: fanuc0m)` (the first line that is
   * not blank or only %), when the page has that profile: as the command line reads it. */
  function namedMachine(text) {
    const first = text.replace(/^\uFEFF/, "").split("\n").find((l) => !/^[\s%]*$/.test(l)) || "";
    const m = /\(\s*ncsight\s*:\s*([^()]*?)\s*\)/i.exec(first);
    return m && [...$("machine").options].some((o) => o.value === m[1]) ? m[1] : null;
  }
  let lastNamed = namedMachine(JOB.text || "");
  /** A first line that names another machine chooses it (opened, restored or typed). */
  function followNamedMachine() {
    const n = namedMachine(programmeText().slice(0, 4096));
    if (n && n !== lastNamed) $("machine").value = n;
    lastNamed = n;
  }
  let debounce = 0;
  ta.addEventListener("input", () => {
    simCurrent = false;
    followNamedMachine();
    countLines(); paintEditor();
    if (!$("auto").checked) return;
    clearTimeout(debounce);
    const size = ta.value.length;
    if (size > 5e6) { banner("warning", t("notrun")); return; }
    debounce = setTimeout(run, size > 2e5 ? 900 : 250);
  });

  // ---- running -----------------------------------------------------------------------------
  function optionsText() {
    const o = [];
    if ($("single").checked) o.push("single_block=1");
    if ($("dry").checked) o.push("dry_run=1");
    if ($("bdel").checked) o.push("block_delete=1");
    if ($("opt").checked) o.push("optional_stop=1");
    if (presses.holds.length) o.push("feed_hold_at=" + presses.holds.join(","));
    if (presses.reset !== null) o.push("reset_at=" + presses.reset);
    o.push("feed_override=" + $("feed-ov").value, "rapid_override=" + $("rapid-ov").value);
    // What the report's command line gave besides (main programme, variables, the runaway guard).
    if (JOB.options && JOB.options.extra) o.push(JOB.options.extra);
    return o.join("\n");
  }
  function banner(cls, text) { const b = $("banner"); b.className = cls; b.textContent = text; }
  /** Run the programme in the editor (in the worker) and show it; a promise of when it is shown,
   * the check's diagnostics included. */
  function run() {
    const generation = ++runs;
    cancelEngine();
    const machine = $("machine").value, params = $("params").value, options = optionsText();
    const t0 = performance.now();
    const textBytes = enc.encode(programmeText());
    // A run that takes a while says so (the page stays usable meanwhile).
    const slow = setTimeout(() => { if (generation === runs) banner("warning", t("running")); }, 300);
    const shown = callEngine("ncsight_scene", textBytes, machine, params, JOB.setup || "", options).then((buf) => {
      clearTimeout(slow);
      if (generation !== runs) return;
      if (!show(parseScene(buf), t0)) return;
      // Then every diagnostic of a check (the run stops at the first alarm; a check goes on),
      // once the path is drawn.
      return callEngine("ncsight_check", textBytes, machine, params, JOB.setup || "", options).then((b) => { if (generation === runs) addCheck(b); }, (e) => { if (e !== CANCELLED) engineFailed("engine error in the check: ", e); });
    }, (e) => { if (e !== CANCELLED) engineFailed("engine error: ", e); });
    inflight = shown;
    return shown;
  }
  /** Show a run's scene; false when the run was refused (a usage mistake). */
  function show(next, t0) {
    lastRunMs = performance.now() - t0;
    if (next.usage) { banner("usage", t("usage", { msg: next.usage })); return false; }
    const wasLathe = lathe;
    S = next;
    lathe = S.head.lathe;
    if (wasLathe !== lathe || !$("view").options.length) { fillViews(); fitted = true; }
    fillPortTargets();
    // A new text or controller: an earlier port is of another programme.
    if (ported && fresh) { ported = null; portScene = null; $("port-save").disabled = true; $("port-status").textContent = ""; $("port-list").textContent = ""; }
    markDiagnostics();
    // A new programme opens at its end (the whole path, the finished part); an edit keeps the moment.
    if (fresh) { pause(); setMachineState("stop", null); }
    now = fresh ? S.head.total_s : Math.min(now, S.head.total_s);
    fresh = false;
    partCache = null;
    if (fitted) fit();
    showProblems(); showTime(); showParams(); legend(); showPasses(); setTime(now, false); paintEditor();
    // A press made while playing: the player may have gone past where the machine stopped in the
    // run made with it (the engine took longer than the hold's pull-out): it goes back there.
    if (pressedAt !== null) {
      doneStop = stopsDoneAt(pressedAt - 1e-6);
      const st = stopBetween(pressedAt - 1e-6, Math.max(now, pressedAt));
      pressedAt = null;
      if (st) { pause(); ticking = true; setTime(st.t, true, st.l); ticking = false; reachedStop(st); }
    }
    // When the first path was drawn, in ms from navigation (what the size tests measure).
    if (!firstPathMs) firstPathMs = performance.now();
    return true;
  }
  /** The run in flight (or the last one) and every later one: resolved when all are shown. */
  let inflight = Promise.resolve();
  async function settled() {
    let p;
    do { p = inflight; await p; } while (p !== inflight);
  }
  /** The engine stopped (a trap, a worker that failed): say so; the next run starts a new one. */
  function engineFailed(what, e) {
    banner("usage", t("usage", { msg: what + String(e.message || e) }));
    stopWorker();
  }
  let runs = 0;
  let firstPathMs = 0;
  function addCheck(buf) {
    const text = new TextDecoder().decode(new Uint8Array(buf));
    if (text.startsWith("NCSE") || !S) return;
    const C = JSON.parse(text), H = S.head;
    // The same diagnostic from the run and the check: same place, code and message (the message
    // names the line of another file).
    const key = (d) => d.l + ":" + d.c + ":" + d.code + ":" + d.msg;
    const seen = new Set(H.diagnostics.map(key));
    const extra = C.diagnostics.filter((d) => !seen.has(key(d)));
    if (!extra.length) return;
    // The run's own stay first, in the order raised; the check's follow, by line.
    extra.sort((a, b) => a.l - b.l || a.c - b.c).forEach((d) => { d.check = true; });
    const room = Math.max(0, 10000 - H.diagnostics.length);
    H.diagnostics.push(...extra.slice(0, room));
    H.diagnostics_total = Math.max(H.diagnostics_total + extra.length, C.total);
    H.alarms_total = Math.max(H.alarms_total || 0, C.alarms || 0);
    markDiagnostics();
    showProblems(); paintEditor(); draw();
  }
  /** Each line's worst diagnostic, for the gutter and the source's bands. */
  function markDiagnostics() {
    diagByLine = new Map();
    S.head.diagnostics.forEach((d) => { if (diagByLine.get(d.l) !== "alarm") diagByLine.set(d.l, d.sev); });
  }
  let lastRunMs = 0;
  function showProblems() {
    const H = S.head, box = $("problems");
    box.textContent = "";
    const alarms = Math.max(H.alarms_total || 0, H.diagnostics.filter((d) => d.sev === "alarm").length);
    const warnings = Math.max(0, H.diagnostics_total - alarms);
    const nf = stockFindings().length;
    const cut = H.cut ? " — " + t("cut", { n: (H.segments + H.events.length).toLocaleString() }) : "";
    // The operator's presses change the run: the banner says so (a hold makes it longer).
    const pressed = presses.holds.length || presses.reset !== null ? " — " + t("withholds", { list: pressList().join(", ") }) : "";
    if (nf) banner("alarm", t("findings", { n: nf }) + (H.diagnostics_total ? " — " + t("problems", { alarms, warnings }) : ""));
    else if (!H.diagnostics_total) {
      if (cut) banner("warning", t("ok", { status: t(H.status), time: hms(H.total_s) }) + cut + pressed);
      else banner("ok", programmeText().trim() ? t("ok", { status: t(H.status), time: hms(H.total_s) }) + pressed : t("empty"));
    } else {
      const firstD = H.diagnostics[0];
      banner(alarms ? "alarm" : "warning", t("problems", { alarms, warnings }) + " — " + t("first", { line: firstD.l, msg: firstD.code + " " + (titleOf(firstD) ? titleOf(firstD) + ": " : "") + firstD.msg }) + cut + pressed);
    }
    const frag = document.createDocumentFragment();
    // What the stock simulation could not do, and its findings (crash, chuck, phase, deviation),
    // come first.
    if (JOB.sim_error && simCurrent) frag.appendChild(el("div", { class: "p warning notice" }, t("simerror") + ": " + JOB.sim_error));
    (simCurrent && JOB.sim && JOB.sim.findings ? JOB.sim.findings : []).filter((f) => f.kind === "not_simulated").forEach((f) => frag.appendChild(el("div", { class: "p warning notice" }, t("notsim") + " (" + t("line") + " " + f.line + "): " + f.message)));
    stockFindings().forEach((f) => {
      const p = el("div", { class: "p alarm finding", "data-line": f.line }, t("stockfinding") + " · " + f.kind + " · " + t("line") + " " + f.line + (f.x !== undefined ? " · X " + f.x + " Z " + f.z : "") + " · " + f.message);
      p.addEventListener("click", () => { select(f.line, true); if (f.t !== undefined) setTime(f.t); });
      frag.appendChild(p);
    });
    H.diagnostics.slice(0, 500).forEach((d) => {
      const title = titleOf(d);
      const p = el("div", { class: "p " + d.sev, "data-line": d.l }, t("line") + " " + d.l + " " + t("col") + " " + d.c + " · " + d.code + (title ? " " + title : "") + " · " + d.msg + (d.hint ? " (" + d.hint + ")" : "") + (d.check ? " " + t(H.status === "ended" ? "bycheck_ended" : "bycheck") : ""));
      p.addEventListener("click", () => { select(d.l, true); explain(d); });
      frag.appendChild(p);
    });
    if (H.diagnostics_total > 500) frag.appendChild(el("div", {}, t("more", { n: H.diagnostics_total - 500 })));
    box.appendChild(frag);
    // The first alarm (else the first warning) is explained at once; a click explains another.
    const firstD = H.diagnostics.find((d) => d.sev === "alarm") || H.diagnostics[0];
    if (firstD) explain(firstD); else $("explain").hidden = true;
  }
  /** A diagnostic's title in the page's language, from the explanations' catalogue. */
  function titleOf(d) {
    const E = JOB.explain && JOB.explain[d.rule];
    return E ? E.title[lang === "zh" ? 1 : 0] : "";
  }
  let explained = null;
  /** Explain a diagnostic under the list: the controller's number and title, what it means, the
   * usual causes, how to fix it, a wrong and a right example (`ncsight explain`'s catalogue). */
  function explain(d) {
    explained = d;
    const E = JOB.explain && JOB.explain[d.rule], box = $("explain"), z = lang === "zh" ? 1 : 0;
    box.textContent = "";
    box.hidden = false;
    box.className = d.sev;
    const number = d.code + (E && E.fanuc && E.fanuc !== d.code ? " (FANUC " + E.fanuc + ")" : "") + (d.code !== d.rule ? " · " + d.rule : "");
    box.appendChild(el("div", { class: "ex-title" }, number + " · " + (E ? E.title[z] : "") + " · " + t(d.sev === "alarm" ? "alarm" : "warningk")));
    box.appendChild(el("div", { class: "ex-msg" }, t("line") + " " + d.l + ": " + d.msg + (d.hint ? " (" + d.hint + ")" : "")));
    if (!E) return;
    box.appendChild(el("p", {}, E.meaning[z]));
    box.appendChild(el("div", { class: "ex-h" }, t("ex_causes")));
    const ul = el("ul");
    E.causes[z].forEach((c) => ul.appendChild(el("li", {}, c)));
    box.appendChild(ul);
    box.appendChild(el("div", { class: "ex-h" }, t("ex_fix")));
    box.appendChild(el("p", {}, E.fix[z]));
    const ex = el("div", { class: "ex-ab" });
    [["ex_wrong", E.wrong, "wrong"], ["ex_right", E.right, "right"]].forEach(([k, text, cls]) => {
      const col = el("div", { class: cls });
      col.appendChild(el("div", { class: "ex-h" }, t(k) + " (" + E.profile + ")"));
      col.appendChild(el("pre", {}, text));
      ex.appendChild(col);
    });
    box.appendChild(ex);
  }

  // ---- time as a person reads it --------------------------------------------------------------
  function hms(s) {
    if (!(s >= 0)) return "-";
    s = Math.round(s * 10) / 10;
    const h = Math.floor(s / 3600), m = Math.floor((s % 3600) / 60), sec = s - h * 3600 - m * 60;
    return (h ? h + ":" + String(m).padStart(2, "0") : String(m)) + ":" + sec.toFixed(1).padStart(4, "0");
  }
  function showTime() {
    const byTool = new Map(), byOp = new Map();
    const add = (m, k, v) => m.set(k, (m.get(k) || 0) + v);
    // What no motion, dwell or turn takes: spindle waits, tool changes, stops.
    let between = S.head.total_s;
    for (let i = 0; i < S.n; i++) {
      const d = S.t[i] - S.t0[i];
      add(byTool, S.tool[i], d);
      const k = S.kind[i] & 7;
      add(byOp, k === 0 ? t("rapid") : k === 1 ? t("feedk") : k === 2 ? t("arc") : t("threadk"), d);
      between -= d;
    }
    S.head.events.forEach((e) => { if (e.k === "dwell") { add(byOp, t("dwell"), e.s); between -= e.s; } if (e.k === "rotary") { add(byOp, t("turn"), e.s); between -= e.s; } });
    // Tool changes: each change to another tool (the first included: the machine's model starts
    // with no tool known) costs the setting tool_change_s (the setup's
    // [machine] tool_change_s, or N=V in the parameters box; 0 when not given).
    const change = S.head.params.find((p) => p[0] === "tool_change_s");
    const perChange = change ? +change[1] : 0;
    let changes = 0, inUse = null;
    S.head.events.forEach((e) => { if (e.k === "tool") { if (e.tool !== inUse) changes++; inUse = e.tool; } });
    if (changes && perChange > 0) { add(byOp, t("toolchanges", { n: changes, s: numLabel(perChange) }), changes * perChange); between -= changes * perChange; }
    if (between > 1e-6) add(byOp, t("waits"), between);
    const box = $("time");
    box.textContent = "";
    box.appendChild(el("div", { id: "time-total" }, t("total") + " " + hms(S.head.total_s)));
    const table = (title, rows, id) => {
      const tb = el("table", { id });
      const hr = el("tr"); hr.appendChild(el("th", {}, title)); hr.appendChild(el("th", {}, "h:mm:ss")); hr.appendChild(el("th", {}, "%")); tb.appendChild(hr);
      rows.forEach(([k, v]) => {
        const tr = el("tr"); tr.appendChild(el("td", {}, k)); tr.appendChild(el("td", { class: "num" }, hms(v)));
        tr.appendChild(el("td", { class: "num" }, S.head.total_s > 0 ? (100 * v / S.head.total_s).toFixed(1) : "-")); tb.appendChild(tr);
      });
      box.appendChild(tb);
    };
    table(t("bytool"), [...byTool].sort((a, b) => b[1] - a[1]).map(([k, v]) => [toolLabel(k), v]), "time-by-tool");
    table(t("byop"), [...byOp].sort((a, b) => b[1] - a[1]), "time-by-op");
  }
  /** Set parameter `key` to `value` in the parameters box, in place of an earlier setting of it. */
  function setParam(key, value) {
    const lines = $("params").value.split("\n").map((l) => l.trim()).filter((l) => l && l.split("=")[0].trim() !== key);
    lines.push(key + "=" + value);
    $("params").value = lines.join("\n");
    rerun();
  }
  function showParams() {
    const box = $("param-table");
    box.textContent = "";
    const tb = el("table");
    const hr = el("tr"); ["p_param", "p_value", "p_unit", "p_meaning", "p_source"].forEach((h) => hr.appendChild(el("th", {}, t(h)))); tb.appendChild(hr);
    // Each value can be set here: a bit by its box, a number by its field; the setting goes into
    // the parameters box (N=V) and the programme runs again (NO.18 bit 6, the G92 hold, say).
    S.head.params.forEach((p) => {
      const tr = el("tr", { "data-param": p[0] });
      tr.appendChild(el("td", {}, p[0]));
      const td = el("td");
      const input = p[2] === "bit" ? el("input", { type: "checkbox", "data-param": p[0] }) : el("input", { type: "number", step: "any", size: "8", "data-param": p[0] });
      if (p[2] === "bit") input.checked = Number(p[1]) === 1; else input.value = String(p[1]);
      input.addEventListener("change", () => setParam(p[0], p[2] === "bit" ? (input.checked ? "1" : "0") : input.value));
      td.appendChild(input);
      tr.appendChild(td);
      // unit, meaning (in Chinese in the Chinese page), source
      [p[2], lang === "zh" && p[5] ? p[5] : p[3], p[4]].forEach((c) => tr.appendChild(el("td", {}, c)));
      tb.appendChild(tr);
    });
    (JOB.settings || []).forEach((s) => box.appendChild(el("div", {}, s)));
    box.appendChild(tb);
  }

  // ---- geometry ------------------------------------------------------------------------------
  const PLANE_AXES = [[0, 1, 2], [2, 0, 1], [1, 2, 0]];
  /** The point at fraction f of motion i (arcs along their circle, helices along their axis). */
  function pointAt(i, f, out) {
    const p = S.p, o = 6 * i;
    const k = S.kind[i] & 7;
    if (k === 2 || k === 4) {
      const ax = PLANE_AXES[(S.kind[i] >> 3) & 3], a = ax[0], b = ax[1], nn = ax[2];
      const c = 4 * i, ca = S.arc[c + a], cb = S.arc[c + b];
      const r = Math.hypot(p[o + a] - ca, p[o + b] - cb);
      const th = Math.atan2(p[o + b] - cb, p[o + a] - ca) + f * S.arc[c + 3];
      out[a] = ca + r * Math.cos(th); out[b] = cb + r * Math.sin(th); out[nn] = p[o + nn] + f * (p[o + 3 + nn] - p[o + nn]);
      return out;
    }
    out[0] = p[o] + f * (p[o + 3] - p[o]); out[1] = p[o + 1] + f * (p[o + 4] - p[o + 1]); out[2] = p[o + 2] + f * (p[o + 5] - p[o + 2]);
    return out;
  }
  const V = () => VIEWS[view.kind] || VIEWS.lathe;
  let cw = 800, ch = 500;
  const sx = (u) => (u - view.ou) * view.s;
  const sy = (v) => ch - (v - view.ov) * view.s;
  // A point's place on the screen in the view whose axes are A (across) and B (up).
  const screenX = (A, q) => sx(A[0] * q[0] + A[1] * q[1] + A[2] * q[2]);
  const screenY = (B, q) => sy(B[0] * q[0] + B[1] * q[1] + B[2] * q[2]);
  /** The box of the cutting moves' end points projected on the view (u0, u1, v0, v1; Infinity
   * without a cutting move), worked out once per run and view (each view's `pu` goes with one
   * `pv`): the fit, the extents' dimensions and the guessed stock read it. */
  let cutCache = null;
  function cutBox(A, B) {
    if (!cutCache || cutCache.S !== S) cutCache = { S, boxes: new Map() };
    if (cutCache.boxes.has(A)) return cutCache.boxes.get(A);
    const box = [Infinity, -Infinity, Infinity, -Infinity], p = S.p;
    for (let i = 0; i < S.n; i++) {
      if ((S.kind[i] & 7) === 0) continue;
      for (let o = 6 * i; o <= 6 * i + 3; o += 3) {
        const u = A[0] * p[o] + A[1] * p[o + 1] + A[2] * p[o + 2], v = B[0] * p[o] + B[1] * p[o + 1] + B[2] * p[o + 2];
        if (u < box[0]) box[0] = u; if (u > box[1]) box[1] = u; if (v < box[2]) box[2] = v; if (v > box[3]) box[3] = v;
      }
    }
    cutCache.boxes.set(A, box);
    return box;
  }
  function fit() {
    if (!S) return;
    const pv = V(), A = pv.pu, B = pv.pv;
    // The fit is on the cutting moves; tool changes and approaches at rapid are left out.
    let [u0, u1, v0, v1] = cutBox(A, B);
    const p = S.p;
    const addPt = (x, y, z) => { const u = A[0] * x + A[1] * y + A[2] * z, v = B[0] * x + B[1] * y + B[2] * z; if (u < u0) u0 = u; if (u > u1) u1 = u; if (v < v0) v0 = v; if (v > v1) v1 = v; };
    for (let j = 0; j < S.h; j++) addPt(S.holeAt[3 * j], S.holeAt[3 * j + 1], S.holeAt[3 * j + 2]);
    if (!isFinite(u0)) for (let i = 0; i < S.n; i++) { const o = 6 * i; addPt(p[o + 3], p[o + 4], p[o + 5]); }
    if (!isFinite(u0)) { u0 = -10; u1 = 10; v0 = -10; v1 = 10; }
    // The solid view fits the whole bar, both sides of the axis.
    const st = pv.solid ? stock() : null;
    if (st) {
      // The end sections are ellipses reaching R sideways: their widest points too.
      const R = st.diameter / 2;
      for (const z of [st.front - st.length, st.front]) { addPt(R, 0, z); addPt(-R, 0, z); addPt(0, R, z); addPt(0, -R, z); }
    }
    const w = Math.max(u1 - u0, 1e-3), h = Math.max(v1 - v0, 1e-3);
    const m = 0.1;
    view.s = Math.min(cw / (w * (1 + 2 * m)), ch / (h * (1 + 2 * m) + 60 / Math.max(ch, 1) * h));
    view.ou = (u0 + u1) / 2 - cw / 2 / view.s;
    view.ov = (v0 + v1) / 2 - ch / 2 / view.s;
    fitted = true;
  }
  function stock() {
    const m = /^\s*([0-9.]+)\s*[xX×*]\s*([0-9.]+)\s*$/.exec($("stock").value);
    if (m && +m[1] > 0 && +m[2] > 0) return { diameter: +m[1], length: +m[2], front: JOB.stock ? JOB.stock.front_z_mm || 0 : 0, guessed: false };
    if (!lathe || !S || !S.n) return null;
    // A guess from the programme: the largest diameter cut, from Z0 to the deepest cut (the
    // lathe view's box: Z across, X up).
    const [zMin, , , xMax] = cutBox(VIEWS.lathe.pu, VIEWS.lathe.pv);
    const x = Math.max(0, xMax), z = Math.min(0, zMin);
    if (x <= 0 || z >= 0) return null;
    return { diameter: 2 * x, length: -z + 2, front: 0, guessed: true };
  }

  // ---- the turned part: the outer profile the tool tip leaves, as the programme plays --------
  let partCache = null;
  const COLS = 1200;
  function part(st) {
    const z0 = st.front - st.length, dz = st.length / COLS;
    const i1 = segAt(now);
    if (!partCache || partCache.key !== st.diameter + "x" + st.length + "@" + st.front || partCache.upto > i1) {
      partCache = { key: st.diameter + "x" + st.length + "@" + st.front, upto: 0, r: new Float32Array(COLS).fill(st.diameter / 2) };
    }
    const r = partCache.r, q = [0, 0, 0], a = [0, 0, 0];
    const cutLine = (za, xa, zb, xb) => {
      if (xa < 0 || xb < 0) return;
      let ja = Math.floor((Math.min(za, zb) - z0) / dz), jb = Math.floor((Math.max(za, zb) - z0) / dz);
      if (jb < 0 || ja >= COLS) return;
      ja = Math.max(0, ja); jb = Math.min(COLS - 1, jb);
      for (let j = ja; j <= jb; j++) {
        const zc = z0 + (j + 0.5) * dz;
        const x = Math.abs(zb - za) < 1e-9 ? Math.min(xa, xb) : xa + (xb - xa) * Math.min(1, Math.max(0, (zc - za) / (zb - za)));
        if (x < r[j]) r[j] = x;
      }
    };
    const cutSeg = (i, fEnd) => {
      const k = S.kind[i] & 7;
      if (k === 0) return;
      const steps = k === 2 || k === 4 ? 24 : 1;
      pointAt(i, 0, a);
      for (let s = 1; s <= steps; s++) { pointAt(i, (s / steps) * fEnd, q); cutLine(a[2], a[0], q[2], q[0]); a[0] = q[0]; a[1] = q[1]; a[2] = q[2]; }
    };
    for (let i = partCache.upto; i < i1; i++) cutSeg(i, 1);
    partCache.upto = Math.max(partCache.upto, i1);
    // The motion under way, up to where the tool is (not kept).
    const out = Float32Array.from(r);
    if (i1 >= 0 && i1 < S.n && now > S.t0[i1]) {
      const keep = r.slice();
      cutSeg(i1, Math.min(1, (now - S.t0[i1]) / Math.max(1e-12, S.t[i1] - S.t0[i1])));
      out.set(r); r.set(keep);
    }
    return { z0, dz, r: out };
  }

  // ---- drawing -------------------------------------------------------------------------------
  const canvas = $("plot");
  const ctx = canvas.getContext("2d");
  let lastDrawMs = 0;
  function niceStep(raw) { const p = Math.pow(10, Math.floor(Math.log10(raw))); for (const m of [1, 2, 5, 10]) if (m * p >= raw) return m * p; return 10 * p; }
  function numLabel(v) { const a = Math.abs(v); return (a >= 100 || Math.abs(v - Math.round(v)) < 1e-9 ? Math.round(v) : +v.toFixed(a >= 10 ? 1 : 3)).toString(); }
  function draw() {
    const t0 = performance.now();
    if (is3d()) { draw3d(); lastDrawMs = performance.now() - t0; return; }
    hide3d();
    const dpr = window.devicePixelRatio || 1;
    const box = $("plot-box");
    cw = box.clientWidth; ch = box.clientHeight;
    if (canvas.width !== Math.round(cw * dpr) || canvas.height !== Math.round(ch * dpr)) { canvas.width = Math.round(cw * dpr); canvas.height = Math.round(ch * dpr); }
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = "#ffffff"; ctx.fillRect(0, 0, cw, ch);
    drawGrid();
    if (!S) { lastDrawMs = performance.now() - t0; return; }
    const pv = V(), A = pv.pu, B = pv.pv;
    const st = lathe ? stock() : null;
    if (st && pv.solid) drawSolid(st);
    else if (st) drawStock(st);
    if (lathe) {
      // The spindle centre line, over the part.
      ctx.strokeStyle = "#455a64"; ctx.lineWidth = 1.2; ctx.setLineDash([14, 4, 3, 4]);
      ctx.beginPath(); ctx.moveTo(0, sy(0)); ctx.lineTo(cw, sy(0)); ctx.stroke(); ctx.setLineDash([]);
    }
    if (!lathe) drawBlock(A, B);
    for (const f of [drawHold, drawPorted, drawPaths, drawHoles, drawExtents, drawSelection, drawDiagnostics, drawFindings, drawTool]) f(A, B);
    if (!lathe) drawTriad(A, B);
    lastDrawMs = performance.now() - t0;
  }
  /** In HOLD, what the hold made the machine do (a thread's pull-out and return) under a wide
   * amber band, so it is seen without zooming in. */
  function drawHold(A, B) {
    if (machineState !== "hold" || !holdSpan) return;
    const q = [0, 0, 0];
    ctx.strokeStyle = "rgba(255,160,0,0.55)"; ctx.lineWidth = 9; ctx.lineCap = "round";
    ctx.beginPath();
    for (let i = Math.max(0, segAt(holdSpan[0]) - 1); i < S.n && S.t0[i] < holdSpan[1] - 1e-9; i++) {
      if (S.t[i] < holdSpan[0] - 1e-9) continue;
      const m = (S.kind[i] & 7) === 2 || (S.kind[i] & 7) === 4 ? 16 : 1;
      for (let j = 0; j <= m; j++) { pointAt(i, j / m, q); const x = screenX(A, q), y = screenY(B, q); if (j) ctx.lineTo(x, y); else ctx.moveTo(x, y); }
    }
    ctx.stroke(); ctx.lineCap = "butt";
  }
  /** A mill's stock block: the Stock box's XxYxZ (its corner at the work zero, its top at Z0,
   * along +X, +Y and -Z, as `simulate` takes it), else guessed from the cutting moves (dashed). */
  function millBlock() {
    const m = /^\s*([0-9.]+)\s*[xX×*]\s*([0-9.]+)\s*[xX×*]\s*([0-9.]+)\s*$/.exec($("stock").value);
    if (m && +m[1] > 0 && +m[2] > 0 && +m[3] > 0) return { min: [0, 0, -m[3]], max: [+m[1], +m[2], 0], guessed: false };
    if (!S || !S.n) return null;
    const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < S.n; i++) {
      if ((S.kind[i] & 7) === 0) continue;
      for (let a = 0; a < 3; a++) { const v = S.p[6 * i + 3 + a]; if (v < min[a]) min[a] = v; if (v > max[a]) max[a] = v; }
    }
    if (!(min[0] < Infinity)) return null;
    // A margin of 5 mm around the cuts in X and Y (a row of holes is not a block of no width).
    return { min: [min[0] - 5, min[1] - 5, Math.min(min[2], -1)], max: [max[0] + 5, max[1] + 5, 0], guessed: true };
  }
  function drawBlock(A, B) {
    const b = millBlock();
    if (!b) return;
    const c = (i) => [i & 1 ? b.max[0] : b.min[0], i & 2 ? b.max[1] : b.min[1], i & 4 ? b.max[2] : b.min[2]];
    ctx.strokeStyle = "#8d6e63"; ctx.lineWidth = 1.2; ctx.setLineDash(b.guessed ? [6, 4] : []);
    ctx.beginPath();
    for (let i = 0; i < 8; i++) for (const bit of [1, 2, 4]) {
      if (i & bit) continue;
      const p = c(i), q = c(i | bit);
      ctx.moveTo(screenX(A, p), screenY(B, p)); ctx.lineTo(screenX(A, q), screenY(B, q));
    }
    ctx.stroke(); ctx.setLineDash([]);
    ctx.fillStyle = "#6d4c41"; ctx.font = "12px system-ui,sans-serif";
    const label = t(b.guessed ? "blockguess" : "block", { x: numLabel(b.max[0] - b.min[0]), y: numLabel(b.max[1] - b.min[1]), z: numLabel(b.max[2] - b.min[2]) });
    ctx.fillStyle = "rgba(255,255,255,0.85)"; ctx.fillRect(92, ch - 26, ctx.measureText(label).width + 8, 18);
    ctx.fillStyle = "#6d4c41"; ctx.fillText(label, 96, ch - 12);
  }
  /** The axes' directions in the view, at the bottom left: X red, Y green, Z blue. */
  function drawTriad(A, B) {
    const ox = 44, oy = ch - 44, len = 30;
    [["X", [1, 0, 0], "#c62828"], ["Y", [0, 1, 0], "#2e7d32"], ["Z", [0, 0, 1], "#1565c0"]].forEach(([name, d, colour]) => {
      const u = A[0] * d[0] + A[1] * d[1] + A[2] * d[2], v = B[0] * d[0] + B[1] * d[1] + B[2] * d[2];
      if (Math.hypot(u, v) < 0.05) { ctx.fillStyle = colour; ctx.beginPath(); ctx.arc(ox, oy, 3, 0, 7); ctx.fill(); ctx.fillText(name, ox + 5, oy + 14); return; }
      const x = ox + len * u, y = oy - len * v;
      ctx.strokeStyle = colour; ctx.fillStyle = colour; ctx.lineWidth = 2;
      ctx.beginPath(); ctx.moveTo(ox, oy); ctx.lineTo(x, y); ctx.stroke();
      ctx.font = "bold 12px system-ui,sans-serif"; ctx.fillText(name, x + 3 * Math.sign(u || 1), y - 3);
    });
  }
  /** The turned part as a solid of revolution: its cross-sections from the chuck forward, each an
   * ellipse (the yaw of the view), shaded as a lit cylinder; edges where the diameter steps. */
  function drawSolid(st) {
    const P = part(st), yaw = Math.asin(V().pu[1]), cz = Math.cos(yaw), sz = Math.sin(yaw);
    const grad = (r) => {
      const g = ctx.createLinearGradient(0, sy(r), 0, sy(-r));
      g.addColorStop(0, "#eceff1"); g.addColorStop(0.35, "#b0bec5"); g.addColorStop(1, "#455a64");
      return g;
    };
    let last = -1;
    for (let j = 0; j < COLS; j++) {
      const r = P.r[j];
      if (r <= 0) { last = r; continue; }
      const x = sx((P.z0 + (j + 0.5) * P.dz) * cz);
      ctx.fillStyle = grad(r);
      ctx.beginPath(); ctx.ellipse(x, sy(0), Math.max(0.5, r * sz * view.s), r * view.s, 0, 0, 2 * Math.PI); ctx.fill();
      if (Math.abs(r - last) > 1e-6) { ctx.strokeStyle = "rgba(38,50,56,0.6)"; ctx.lineWidth = 1; ctx.stroke(); }
      last = r;
    }
    // The front face, lit flat.
    const rf = P.r[COLS - 1];
    if (rf > 0) {
      ctx.fillStyle = "#cfd8dc"; ctx.strokeStyle = "#37474f";
      ctx.beginPath(); ctx.ellipse(sx((P.z0 + COLS * P.dz) * cz), sy(0), Math.max(0.5, rf * sz * view.s), rf * view.s, 0, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
    }
  }
  function drawGrid() {
    if (V().solid) { ctx.fillStyle = "#f4f6f8"; ctx.fillRect(0, 0, cw, ch); return; }
    const step = niceStep(80 / view.s), minor = step / 5;
    const u0 = view.ou, u1 = view.ou + cw / view.s, v0 = view.ov, v1 = view.ov + ch / view.s;
    ctx.lineWidth = 1;
    if (minor * view.s >= 8) {
      ctx.strokeStyle = "#f1f3f5"; ctx.beginPath();
      for (let u = Math.ceil(u0 / minor) * minor; u <= u1; u += minor) { const x = Math.round(sx(u)) + 0.5; ctx.moveTo(x, 0); ctx.lineTo(x, ch); }
      for (let v = Math.ceil(v0 / minor) * minor; v <= v1; v += minor) { const y = Math.round(sy(v)) + 0.5; ctx.moveTo(0, y); ctx.lineTo(cw, y); }
      ctx.stroke();
    }
    ctx.strokeStyle = "#dde2e7"; ctx.beginPath();
    for (let u = Math.ceil(u0 / step) * step; u <= u1; u += step) { const x = Math.round(sx(u)) + 0.5; ctx.moveTo(x, 0); ctx.lineTo(x, ch); }
    for (let v = Math.ceil(v0 / step) * step; v <= v1; v += step) { const y = Math.round(sy(v)) + 0.5; ctx.moveTo(0, y); ctx.lineTo(cw, y); }
    ctx.stroke();
    // The axes through the work zero, and on a lathe the spindle centre line.
    const zx = sx(0), zy = sy(0);
    ctx.strokeStyle = "#455a64"; ctx.lineWidth = 1.2;
    ctx.setLineDash(lathe ? [14, 4, 3, 4] : []);
    ctx.beginPath(); ctx.moveTo(0, zy); ctx.lineTo(cw, zy); ctx.stroke();
    ctx.setLineDash([]);
    ctx.beginPath(); ctx.moveTo(zx, 0); ctx.lineTo(zx, ch); ctx.stroke();
    // Ticks and numbers along the bottom and the left edge (a lathe's X as a diameter).
    ctx.fillStyle = "rgba(255,255,255,0.85)"; ctx.fillRect(0, ch - 18, cw, 18); ctx.fillRect(0, 0, 44, ch);
    ctx.fillStyle = "#37474f"; ctx.font = "11px system-ui,sans-serif"; ctx.textBaseline = "middle";
    ctx.strokeStyle = "#37474f"; ctx.lineWidth = 1; ctx.beginPath();
    ctx.textAlign = "center";
    for (let u = Math.ceil(u0 / step) * step; u <= u1; u += step) { const x = sx(u); if (x < 50) continue; ctx.moveTo(x, ch - 18); ctx.lineTo(x, ch - 13); ctx.fillText(numLabel(u), x, ch - 7); }
    ctx.textAlign = "right";
    for (let v = Math.ceil(v0 / step) * step; v <= v1; v += step) { const y = sy(v); if (y > ch - 22) continue; ctx.moveTo(44, y); ctx.lineTo(39, y); ctx.fillText(numLabel(lathe ? 2 * v : v), 37, y); }
    ctx.stroke();
    const names = V().names;
    ctx.font = "bold 12px system-ui,sans-serif"; ctx.textAlign = "right"; ctx.fillText(names[0] + " mm", cw - 6, ch - 26);
    ctx.textAlign = "left"; ctx.fillText(names[1] + " mm", 48, 10);
    // The work zero: a quartered circle.
    if (zx > -10 && zx < cw + 10 && zy > -10 && zy < ch + 10) {
      ctx.fillStyle = "#263238"; ctx.beginPath(); ctx.moveTo(zx, zy); ctx.arc(zx, zy, 6, 0, Math.PI / 2); ctx.closePath(); ctx.fill();
      ctx.beginPath(); ctx.moveTo(zx, zy); ctx.arc(zx, zy, 6, Math.PI, 1.5 * Math.PI); ctx.closePath(); ctx.fill();
      ctx.strokeStyle = "#263238"; ctx.beginPath(); ctx.arc(zx, zy, 6, 0, 2 * Math.PI); ctx.stroke();
    }
  }
  function drawStock(st) {
    const zb = st.front - st.length, R = st.diameter / 2;
    // The chuck: jaws gripping the far end of the bar, and its body behind.
    const grip = Math.min(15, st.length * 0.25), jaw = Math.max(6, st.diameter * 0.18);
    ctx.fillStyle = "#78909c";
    ctx.fillRect(sx(zb - 30), sy(R + jaw + 12), 30 * view.s, (2 * (R + jaw + 12)) * view.s);
    ctx.fillStyle = "#90a4ae";
    [1, -1].forEach((sgn) => { const y0 = sy(sgn > 0 ? R + jaw : -R), y1 = sy(sgn > 0 ? R : -R - jaw); ctx.fillRect(sx(zb), y0, grip * view.s, y1 - y0); });
    // The part: the profile left by the tool, mirrored about the axis, shaded.
    const P = part(st);
    ctx.fillStyle = "rgba(176,190,197,0.75)"; ctx.strokeStyle = "#546e7a"; ctx.lineWidth = 1;
    [1, -1].forEach((sgn) => {
      ctx.beginPath(); ctx.moveTo(sx(P.z0), sy(0));
      for (let j = 0; j < COLS; j++) { ctx.lineTo(sx(P.z0 + j * P.dz), sy(sgn * P.r[j])); ctx.lineTo(sx(P.z0 + (j + 1) * P.dz), sy(sgn * P.r[j])); }
      ctx.lineTo(sx(P.z0 + COLS * P.dz), sy(0)); ctx.closePath(); ctx.fill(); ctx.stroke();
    });
    // The bar as it was.
    ctx.setLineDash([5, 4]); ctx.strokeStyle = st.guessed ? "#b0bec5" : "#78909c";
    ctx.strokeRect(sx(zb), sy(R), st.length * view.s, 2 * R * view.s); ctx.setLineDash([]);
  }
  /** One style's path, thinned to what the pixels can show: a point closer than 0.6 px to the
   * last one drawn is skipped, so a million short moves draw as fast as the screen is wide. */
  function drawPaths(A, B) {
    const n = S.n, p = S.p, kind = S.kind, styleOf = S.style;
    const iNow = segAt(now);
    const buckets = [];
    const q = [0, 0, 0];
    const W = cw + 50, Hh = ch + 50;
    const a0 = A[0], a1 = A[1], a2 = A[2], b0 = B[0], b1 = B[1], b2 = B[2], s = view.s, ou = view.ou, ov = view.ov;
    for (let i = 0; i < n; i++) {
      const o = 6 * i, k = kind[i] & 7;
      const x0 = (a0 * p[o] + a1 * p[o + 1] + a2 * p[o + 2] - ou) * s, y0 = ch - (b0 * p[o] + b1 * p[o + 1] + b2 * p[o + 2] - ov) * s;
      const x1 = (a0 * p[o + 3] + a1 * p[o + 4] + a2 * p[o + 5] - ou) * s, y1 = ch - (b0 * p[o + 3] + b1 * p[o + 4] + b2 * p[o + 5] - ov) * s;
      const arcy = k === 2 || k === 4;
      if (!arcy && ((x0 < -50 && x1 < -50) || (x0 > W && x1 > W) || (y0 < -50 && y1 < -50) || (y0 > Hh && y1 > Hh))) continue;
      const key = styleOf[i] * 2 + (i <= iNow ? 1 : 0);
      let b = buckets[key];
      if (!b) b = buckets[key] = { path: new Path2D(), x: NaN, y: NaN, key };
      // Nothing to draw: a move along the line of sight that starts where the last one ended.
      if (!arcy && Math.abs(x1 - b.x) < 0.6 && Math.abs(y1 - b.y) < 0.6 && Math.abs(x0 - b.x) < 0.6 && Math.abs(y0 - b.y) < 0.6) continue;
      if (!(Math.abs(x0 - b.x) < 0.6 && Math.abs(y0 - b.y) < 0.6)) { b.path.moveTo(x0, y0); b.x = x0; b.y = y0; }
      if (arcy) {
        const c = 4 * i;
        const ax = PLANE_AXES[(kind[i] >> 3) & 3];
        const r = Math.hypot(p[o + ax[0]] - S.arc[c + ax[0]], p[o + ax[1]] - S.arc[c + ax[1]]) * view.s;
        const sweep = Math.abs(S.arc[c + 3]);
        // Chords within a quarter pixel of the circle.
        const m = r < 1 ? 1 : Math.min(720, Math.max(2, Math.ceil(sweep / (2 * Math.acos(Math.max(-1, 1 - 0.25 / r))))));
        for (let j = 1; j <= m; j++) {
          pointAt(i, j / m, q);
          const x = screenX(A, q), y = screenY(B, q);
          if (j === m || Math.abs(x - b.x) >= 0.6 || Math.abs(y - b.y) >= 0.6) { b.path.lineTo(x, y); b.x = x; b.y = y; }
        }
      } else if (Math.abs(x1 - b.x) >= 0.6 || Math.abs(y1 - b.y) >= 0.6) { b.path.lineTo(x1, y1); b.x = x1; b.y = y1; }
    }
    const order = buckets.filter(Boolean);
    for (const b of order) {
      const style = b.key >> 1, done = b.key & 1;
      ctx.globalAlpha = done ? 1 : 0.3;
      // Dashes cost much in a software canvas: a programme with many rapids draws them thin and solid.
      ctx.setLineDash(style === 0 && n < 50000 ? [4, 3] : []);
      ctx.lineWidth = style === 0 ? 1 : style === 1 ? 2 : style % 2 ? 2.2 : 1.5;
      // Style 2 + 2t / 3 + 2t: the tool t in order of appearance (t = 0: before any tool).
      const ti = (style >> 1) - 1;
      ctx.strokeStyle = style === 0 ? "#9e9e9e" : style === 1 ? "#8e24aa" : ti === 0 ? "#37474f" : PALETTE[(ti - 1) % PALETTE.length];
      ctx.stroke(b.path);
    }
    ctx.globalAlpha = 1; ctx.setLineDash([]);
  }
  // Eight closed shapes; past eight cycle kinds the colour moves on, so no two kinds look alike.
  const SHAPES = ["circle", "square", "triangle", "diamond", "down", "hexagon", "bar", "column"];
  const holeLook = (k) => ({ shape: SHAPES[k % 8], colour: HOLE_COLOURS[(k + 3 * Math.floor(k / 8)) % HOLE_COLOURS.length] });
  function marker(path, x, y, shape, r) {
    const poly = (pts) => { path.moveTo(x + pts[0][0], y + pts[0][1]); for (let i = 1; i < pts.length; i++) path.lineTo(x + pts[i][0], y + pts[i][1]); path.closePath(); };
    if (shape === "circle") { path.moveTo(x + r, y); path.arc(x, y, r, 0, 2 * Math.PI); }
    else if (shape === "square") path.rect(x - r, y - r, 2 * r, 2 * r);
    else if (shape === "triangle") poly([[0, -r], [r, r], [-r, r]]);
    else if (shape === "down") poly([[0, r], [r, -r], [-r, -r]]);
    else if (shape === "diamond") poly([[0, -r], [r, 0], [0, r], [-r, 0]]);
    else if (shape === "hexagon") poly([0, 1, 2, 3, 4, 5].map((i) => [r * Math.cos(i * Math.PI / 3), r * Math.sin(i * Math.PI / 3)]));
    else if (shape === "bar") path.rect(x - r, y - r / 2, 2 * r, r);
    else path.rect(x - r / 2, y - r, r, 2 * r);
  }
  function drawHoles(A, B) {
    if (!S.h) return;
    // One marker per cell of its own size and per cycle (markers that would overlap are not
    // drawn): 200,000 holes cost what the screen can show. Each cycle at a hole has its own
    // size, the later cycles larger, so a spot drill, a drill and a tap at one hole all show.
    // Holes drilled by now are filled; those to come open.
    const r0 = Math.max(3, Math.min(7, 1.5 * view.s)), kinds = S.head.hole_kinds.length;
    const size = (k) => r0 + 3 * Math.min(k, 5);
    const cell = 2 * r0 + 1, gw = Math.ceil(cw / cell) + 1, seen = new Uint32Array(gw * (Math.ceil(ch / cell) + 2));
    const paths = S.head.hole_kinds.map(() => [new Path2D(), new Path2D()]);
    for (let j = 0; j < S.h; j++) {
      const o = 3 * j;
      const x = sx(A[0] * S.holeAt[o] + A[1] * S.holeAt[o + 1] + A[2] * S.holeAt[o + 2]), y = sy(B[0] * S.holeAt[o] + B[1] * S.holeAt[o + 1] + B[2] * S.holeAt[o + 2]);
      if (x < -8 || y < -8 || x > cw + 8 || y > ch + 8) continue;
      const c = Math.floor(Math.max(0, y) / cell) * gw + Math.floor(Math.max(0, x) / cell);
      const k = S.holeKind[j], bit = 1 << (k & 31);
      if (seen[c] & bit) continue;
      seen[c] |= bit;
      marker(paths[k][S.t[S.holeSeg[j]] <= now + 1e-9 ? 1 : 0], x, y, holeLook(k).shape, size(k));
    }
    // The largest first, so that the smaller markers stay on top.
    for (let k = kinds - 1; k >= 0; k--) {
      const [open, done] = paths[k], colour = holeLook(k).colour;
      ctx.lineWidth = 1.6; ctx.strokeStyle = colour;
      ctx.fillStyle = "#ffffff"; ctx.fill(open); ctx.fillStyle = colour; ctx.fill(done);
      ctx.stroke(open); ctx.stroke(done);
    }
  }

  function drawExtents(A, B) {
    // The extents of the cutting moves, dimensioned below and to the right of them.
    const [u0, u1, v0, v1] = cutBox(A, B);
    if (!isFinite(u0) || view.kind === "iso" || V().solid) return;
    ctx.strokeStyle = "#00695c"; ctx.fillStyle = "#00695c"; ctx.lineWidth = 1; ctx.font = "11px system-ui,sans-serif";
    const yb = Math.min(ch - 26, sy(lathe ? Math.min(v0, -(v1)) : v0) + 16), xr = Math.min(cw - 30, sx(u1) + 16);
    const arrow = (x0, y0, x1, y1) => {
      ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(x1, y1); ctx.stroke();
      const a = Math.atan2(y1 - y0, x1 - x0);
      for (const [x, y, d] of [[x0, y0, a], [x1, y1, a + Math.PI]]) { ctx.beginPath(); ctx.moveTo(x, y); ctx.lineTo(x + 6 * Math.cos(d + 0.35), y + 6 * Math.sin(d + 0.35)); ctx.lineTo(x + 6 * Math.cos(d - 0.35), y + 6 * Math.sin(d - 0.35)); ctx.closePath(); ctx.fill(); }
    };
    if (u1 - u0 > 1e-6) {
      arrow(sx(u0), yb, sx(u1), yb);
      ctx.textAlign = "center"; ctx.textBaseline = "bottom";
      ctx.fillText((u1 - u0).toFixed(3) + "  (" + V().names[0] + " " + numLabel(u0) + " … " + numLabel(u1) + ")", (sx(u0) + sx(u1)) / 2, yb - 2);
    }
    if (v1 - v0 > 1e-6) {
      arrow(xr, sy(v0), xr, sy(v1));
      ctx.save(); ctx.translate(xr + 4, (sy(v0) + sy(v1)) / 2); ctx.rotate(-Math.PI / 2); ctx.textAlign = "center"; ctx.textBaseline = "top";
      ctx.fillText(lathe ? "Ø " + numLabel(2 * v0) + " … Ø " + numLabel(2 * v1) : (v1 - v0).toFixed(3) + "  (" + V().names[1] + " " + numLabel(v0) + " … " + numLabel(v1) + ")", 0, 0);
      ctx.restore();
    }
    ctx.textBaseline = "middle";
  }
  function drawSelection(A, B) {
    if (!selLine) return;
    const q = [0, 0, 0];
    ctx.strokeStyle = "rgba(255,179,0,0.9)"; ctx.lineWidth = 5; ctx.lineCap = "round";
    ctx.beginPath();
    for (let i = 0; i < S.n; i++) {
      if (S.line[i] !== selLine) continue;
      const m = (S.kind[i] & 7) === 2 || (S.kind[i] & 7) === 4 ? 48 : 1;
      for (let s = 0; s <= m; s++) { pointAt(i, s / m, q); const x = screenX(A, q), y = screenY(B, q); if (s) ctx.lineTo(x, y); else ctx.moveTo(x, y); }
    }
    ctx.stroke(); ctx.lineCap = "butt";
  }
  /** Where a diagnostic is drawn: where the tool was when the run raised it; one the run did not
   * reach (found by the check) at its line's first motion, if the line has one; else nowhere. */
  function diagPoint(d, out) {
    if (!S.n) return null;
    if (d.seg === undefined) { const i = S.line.indexOf(d.l); return i < 0 ? null : pointAt(i, 0, out); }
    return d.seg > 0 ? pointAt(d.seg - 1, 1, out) : pointAt(0, 0, out);
  }
  function drawDiagnostics(A, B) {
    const q = [0, 0, 0];
    S.head.diagnostics.slice(0, 200).forEach((d) => {
      if (!diagPoint(d, q)) return;
      const x = screenX(A, q), y = screenY(B, q);
      ctx.fillStyle = d.sev === "alarm" ? "#c62828" : "#f9a825";
      ctx.beginPath(); ctx.moveTo(x, y - 16); ctx.lineTo(x + 9, y - 1); ctx.lineTo(x - 9, y - 1); ctx.closePath(); ctx.fill();
      ctx.fillStyle = "#fff"; ctx.font = "bold 11px system-ui,sans-serif"; ctx.textAlign = "center"; ctx.textBaseline = "middle"; ctx.fillText("!", x, y - 6);
    });
  }
  // The stock simulation ran on the programme as written: once it is edited, another file opened or
  // another controller chosen, its findings no longer belong to what is shown.
  let simCurrent = true;
  const stockFindings = () => (simCurrent && JOB.sim && JOB.sim.findings ? JOB.sim.findings : []).filter((f) => f.kind !== "not_simulated");
  function drawFindings(A, B) {
    // Where the stock simulation found a crash, a chuck touch, a phase error or a deviation.
    stockFindings().forEach((f) => {
      if (f.x === undefined) return;
      const p = [f.x / 2, f.y || 0, f.z];
      const x = screenX(A, p), y = screenY(B, p);
      ctx.fillStyle = "#6a1b9a"; ctx.beginPath(); ctx.moveTo(x, y - 9); ctx.lineTo(x + 9, y); ctx.lineTo(x, y + 9); ctx.lineTo(x - 9, y); ctx.closePath(); ctx.fill();
      ctx.fillStyle = "#fff"; ctx.font = "bold 11px system-ui,sans-serif"; ctx.textAlign = "center"; ctx.textBaseline = "middle"; ctx.fillText("!", x, y);
    });
  }
  function drawTool(A, B) {
    const q = posAt(now);
    const x = screenX(A, q), y = screenY(B, q);
    ctx.fillStyle = "#ffb300"; ctx.strokeStyle = "#000"; ctx.lineWidth = 1.5;
    ctx.beginPath(); ctx.arc(x, y, 6, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
    ctx.beginPath(); ctx.moveTo(x - 10, y); ctx.lineTo(x + 10, y); ctx.moveTo(x, y - 10); ctx.lineTo(x, y + 10); ctx.stroke();
  }
  /** A tool's name: the comment of the block that called it (CAM writes "T1 (D10 FLAT END
   * MILL)"; a lathe programme "T0101 (OD TOOL)"), else the comment of the line before it. */
  function toolName(tool) {
    if (!S) return "";
    if (!S.toolNames) {
      S.toolNames = new Map();
      const comment = (l) => { const m = l > 0 ? /\(([^()]*)\)/.exec(sourceLine(l)) : null; return m ? m[1].trim() : ""; };
      S.head.events.forEach((x) => {
        if (x.k !== "tool" || S.toolNames.has(x.tool)) return;
        const before = x.l > 1 && /^\s*\(([^()]*)\)\s*$/.test(sourceLine(x.l - 1)) ? comment(x.l - 1) : "";
        S.toolNames.set(x.tool, comment(x.l) || before);
      });
    }
    return S.toolNames.get(tool) || "";
  }
  const toolLabel = (tool) => "T" + String(tool).padStart(2, "0") + (toolName(tool) ? " " + toolName(tool) : "");
  function legend() {
    const L = $("legend");
    L.textContent = "";
    const item = (colour, text, dashed) => { const s = el("span", { class: "lg" }); const sw = el("span", { class: "sw" }); sw.style.borderTopColor = colour; if (dashed) sw.style.borderTopStyle = "dashed"; s.appendChild(sw); s.appendChild(document.createTextNode(text)); L.appendChild(s); };
    item("#9e9e9e", t("rapid"), true);
    (S.tools.length ? S.tools : [0]).forEach((tool) => item(toolColour(tool), toolLabel(tool)));
    if (S.head.threads.length) item("#8e24aa", t("pullout"));
    S.head.hole_kinds.forEach((k, i) => item(holeLook(i).colour, k + " " + t("hole")));
  }

  // ---- the player ----------------------------------------------------------------------------
  function segAt(time) {
    // The first motion that ends at or after `time` (the one under way), or the last one.
    if (!S || !S.n) return -1;
    let lo = 0, hi = S.n - 1;
    while (lo < hi) { const m = (lo + hi) >> 1; if (S.t[m] < time - 1e-9) lo = m + 1; else hi = m; }
    return time <= 0 && S.t[0] > 0 ? (S.t0[0] < 1e-12 ? 0 : -1) : lo;
  }
  function posAt(time) {
    const out = [0, 0, 0];
    if (!S || !S.n) return out;
    const i = segAt(time);
    if (i < 0) return pointAt(0, 0, out);
    const d = S.t[i] - S.t0[i];
    const f = d > 0 ? Math.min(1, Math.max(0, (time - S.t0[i]) / d)) : 1;
    return pointAt(i, f, out);
  }
  /** Move the player to `time`; the source scrolls to the running line unless `follow` is false
   * (a run again after an edit must not pull the editor away from the caret). */
  function setTime(time, follow, atLine) {
    if (!S) return;
    const total = Math.max(S.head.total_s, 1e-9);
    now = Math.max(0, Math.min(total, time));
    if (!ticking) doneStop = stopsDoneAt(now);
    $("slider").value = String(Math.round(now / total * 10000));
    const i = segAt(now);
    // Between motions (a dwell, a spindle wait, a tool change) the record under way is not a motion.
    // Records after the last motion (a dwell, M05, M30) and before the first are found too.
    const under = (seg) => (S.eventsBefore.get(seg) || []).find((e) => e.t >= now - 1e-9) || null;
    const between = i < 0 ? under(0) : now > S.t[S.n - 1] + 1e-9 ? under(S.n) : now < S.t0[i] - 1e-9 ? under(i) : null;
    // `atLine`: the record the caller went to (a tool change at the moment a move ends).
    const line = atLine || (between ? between.l : i >= 0 ? S.line[i] : 0);
    if (line !== runLine) { runLine = line; if (runLine && follow !== false) showLine(runLine, false); else paintEditor(); }
    updateState(i, between);
    draw();
  }
  function updateState(i, between) {
    const q = posAt(now);
    let rpm = 0;
    for (const e of S.head.events) { if (e.t > now + 1e-9) break; if (e.k === "spindle") rpm = e.rpm; }
    const k = i >= 0 ? S.kind[i] & 7 : -1;
    const th = i >= 0 ? S.threadOf.get(i) : null;
    const pos = lathe ? "X " + (2 * q[0]).toFixed(3) + " (Ø)  Z " + q[2].toFixed(3) : "X " + q[0].toFixed(3) + "  Y " + q[1].toFixed(3) + "  Z " + q[2].toFixed(3);
    const lines = [
      t("state_t") + " " + hms(now) + " " + t("of") + " " + hms(S.head.total_s) + "   " + t("state_line") + " " + (runLine || "-") + "   " + (between ? between.k : k >= 0 ? t("kinds")[k] : "") + (i >= 0 ? "   " + toolLabel(S.tool[i]) : ""),
      pos,
      t("spindle") + " " + (th ? th[2] : rpm) + " rpm" + (th ? "   " + t("lead") + " " + S.rate[i] + " mm   " + t("angle") + " " + (((th[1] + 360 * Math.abs(th[2]) * Math.max(0, now - S.t0[i]) / 60) % 360)).toFixed(1) + "°" : k === 1 || k === 2 ? "   " + t("feedrate") + " " + S.rate[i] + " mm/min" : ""),
    ];
    // The block's sequence number, as the controller shows it.
    const nWord = runLine ? /^\s*\/?\s*N\s*(\d+)/i.exec(sourceLine(runLine)) : null;
    if (nWord) lines[0] = lines[0].replace(t("state_line") + " " + runLine, t("state_line") + " " + runLine + " (N" + nWord[1] + ")");
    $("state").textContent = lines.join("\n");
    $("clock").textContent = hms(now);
  }
  // ---- the operator's player: it runs as the machine does and stops where the machine stops ----
  // The run's stop records (single block, M00, M01 with the optional-stop switch, G88, a FEED
  // HOLD pressed, RESET) are where Play stops; CYCLE START goes on from there. The state is
  // shown as the controller's screen shows it: RUN, HOLD, STOP, ALARM.
  let machineState = "stop"; // run | hold | stop | alarm
  let stopWhy = null; // what the last stop was and what the machine did: a function of the language
  let holdSpan = null; // [press, stop] of the hold shown
  let slowed = false; // a thread under way, played at real time so a press can be aimed
  const THREAD_SPEED = 1; // playing speed in a thread: real time
  // The stop records the player has passed: the index of the last in the header's records. Each
  // CYCLE START passes one stop, so stops at the same moment (blocks that take no time under
  // single block) are one press each; a time the player is put at has its stops passed, except
  // at the programme's start, where nothing has run yet.
  let doneStop = -1, ticking = false;
  function stopsDoneAt(time) {
    let done = -1;
    if (!S || time <= 1e-12) return done;
    S.head.events.forEach((e, j) => { if (e.k === "stop" && e.t <= time + 1e-9) done = j; });
    return done;
  }
  /** The first stop record not passed yet, from `from` to `to`, or null. */
  function stopBetween(from, to) {
    if (!S) return null;
    const ev = S.head.events;
    for (let j = doneStop + 1; j < ev.length; j++) {
      const e = ev[j];
      if (e.t > to + 1e-9) break;
      if (e.k === "stop" && e.t >= from - 1e-9) { doneStop = j; return e; }
    }
    return null;
  }
  function setMachineState(state, why) {
    machineState = state;
    stopWhy = why || null;
    const box = $("machine-state");
    box.className = "ms " + state;
    box.textContent = t("ms_" + state);
    $("stop-why").textContent = stopWhy ? stopWhy() : "";
    $("play").classList.toggle("lit", state === "run");
    $("hold").classList.toggle("lit", state === "hold");
    if (S) draw(); // the hold's band comes and goes with the state
  }
  /** CYCLE START: run from where the player is (from the start once at the end). */
  function cycleStart() {
    if (!S || timer) return;
    if (now >= S.head.total_s - 1e-9) setTime(0);
    setMachineState("run");
    let last = performance.now();
    const tick = (ts) => {
      const dt = Math.max(0, (ts - last) / 1000); last = ts;
      const i = segAt(now);
      slowed = i >= 0 && (S.kind[i] & 7) >= 3 && now >= S.t0[i] - 1e-9 && $("slow-threads").checked;
      const speed = slowed ? Math.min(THREAD_SPEED, +$("speed").value) : +$("speed").value;
      const to = now + dt * speed;
      const stop = stopBetween(now, to);
      ticking = true;
      try {
        if (stop) { setTime(stop.t, true, stop.l); pause(); return reachedStop(stop); }
        setTime(to);
      } finally { ticking = false; }
      if (now >= S.head.total_s - 1e-9) { pause(); return reachedEnd(); }
      timer = requestAnimationFrame(tick);
    };
    timer = requestAnimationFrame(tick);
  }
  /** The player pauses (the viewer's pause: the machine would go on). */
  function pause() {
    if (timer) cancelAnimationFrame(timer);
    timer = 0;
    slowed = false;
    $("pause").disabled = true;
    if (machineState === "run") setMachineState("stop", () => t("why_paused"));
  }
  function playPause() { if (timer) pause(); else { cycleStart(); $("pause").disabled = !timer; } }
  /** The player reached a stop record: the state and what the machine did. */
  function reachedStop(e) {
    const why = { program_stop: "why_m00", optional_stop: "why_m01", manual_retract: "why_g88", single_block: "why_single", reset: "why_reset" }[e.reason];
    if (e.reason === "feed_hold") return setMachineState("hold", holdStory(e));
    setMachineState("stop", () => t(why || "why_stop", { line: e.l }));
  }
  function reachedEnd() {
    const H = S.head;
    if (H.status === "alarm") {
      const d = H.diagnostics.find((x) => x.sev === "alarm" && !x.check) || H.diagnostics[0];
      setMachineState("alarm", d ? () => t("why_alarm", { line: d.l, code: d.code, title: titleOf(d) }) : null);
      if (d) explain(d);
    } else { const key = H.status === "ended" ? "why_end" : presses.reset !== null ? "why_reset" : "why_textend"; setMachineState("stop", () => t(key)); }
  }
  /** What a FEED HOLD did, read from the run's records between the press and the stop. */
  function holdStory(e) {
    const press = presses.holds.filter((x) => x <= e.t + 1e-9).pop();
    if (press === undefined || !S) return () => t("why_hold", { t: "-" });
    holdSpan = [press, e.t];
    let threadCut = false, pulled = false, back = false, finished = false;
    for (let i = Math.max(0, segAt(press)); i < S.n && S.t0[i] < e.t - 1e-9; i++) {
      const k = S.kind[i] & 7;
      if (k >= 3 && !(S.kind[i] & 32) && S.t0[i] <= press + 1e-9 && S.t[i] >= press - 1e-9) {
        // The thread motion under way at the press: cut short there, or finished.
        threadCut = true;
        finished = S.t[i] > press + 1e-6;
      }
      if (S.kind[i] & 32) pulled = true;
      if (k === 0 && S.t0[i] >= press - 1e-9) back = true;
    }
    if (!threadCut) return () => t(e.t > press + 0.05 ? "why_hold_end" : "why_hold", { t: hms(press) });
    return () => t(finished ? "why_hold_thread_finish" : "why_hold_thread", { t: hms(press), pulled: pulled ? t("why_pulled") : "", back: back ? t("why_back") : "" });
  }
  /** Step to the next (previous) motion's end: each pass of a G71, G92 or G75 on its own. */
  function stepMotion(dir) {
    if (!S || !S.n) return;
    pause();
    if (dir > 0) { const i = segAt(now + 1e-6); if (i >= 0 && S.t[i] > now + 1e-9) return setTime(S.t[i]); for (let k = Math.max(0, i); k < S.n; k++) if (S.t[k] > now + 1e-9) return setTime(S.t[k]); setTime(S.head.total_s); }
    else { for (let k = segAt(now); k >= 0; k--) if (S.t[k] < now - 1e-9) return setTime(S.t[k]); setTime(0); }
  }
  function stepBlock(dir) {
    if (!S) return;
    pause();
    const E = S.blockEnds;
    if (dir > 0) { for (let k = 0; k < E.length; k++) if (E[k] > now + 1e-9) return setTime(E[k]); setTime(S.head.total_s); }
    else { for (let k = E.length - 1; k >= 0; k--) if (E[k] < now - 1e-9) return setTime(E[k]); setTime(0); }
  }
  function nextTool() {
    const e = S && S.head.events.find((x) => x.k === "tool" && x.t > now + 1e-9);
    if (e) setTime(e.t, true, e.l);
    else if (S) setTime(S.head.total_s);
  }
  function toCursor() {
    if (!S) return;
    const n = caretLine();
    for (let i = 0; i < S.n; i++) if (S.line[i] === n && S.t[i] > now + 1e-9) return setTime(S.t[i]);
    for (let i = 0; i < S.n; i++) if (S.line[i] === n) return setTime(S.t[i]);
  }
  function select(line, moveCaret) { selLine = line; showLine(line, moveCaret); draw(); }
  $("play").addEventListener("click", () => { cycleStart(); $("pause").disabled = !timer; });
  $("pause").addEventListener("click", pause);
  $("next-motion").addEventListener("click", () => stepMotion(1));
  $("prev-motion").addEventListener("click", () => stepMotion(-1));
  $("next").addEventListener("click", () => stepBlock(1));
  $("prev").addEventListener("click", () => stepBlock(-1));
  $("next-tool").addEventListener("click", nextTool);
  $("to-cursor").addEventListener("click", toCursor);
  $("slider").addEventListener("input", (e) => { if (S) { pause(); setTime(e.target.value / 10000 * S.head.total_s); } });

  // ---- the operator panel: each press runs the programme again ---------------------------------
  const rerun = () => { run(); showPresses(); };
  function pressList() {
    const list = presses.holds.map((x) => t("holdat", { t: x.toFixed(2) }));
    if (presses.reset !== null) list.push(t("resetat", { t: presses.reset.toFixed(2) }));
    return list;
  }
  function showPresses() {
    const list = pressList();
    $("presses").textContent = list.length ? t("presses", { list: list.join(", ") }) : "";
  }
  // FEED HOLD and RESET press the button at the moment the player shows; playing, the player goes
  // on in the run made again with the press, to where the machine stops.
  let pressedAt = null; // a FEED HOLD pressed while playing, until the run made with it is shown
  $("hold").addEventListener("click", () => {
    const at = +now.toFixed(3);
    if (presses.holds.includes(at)) return;
    presses.holds.push(at); presses.holds.sort((a, b) => a - b);
    if (timer) pressedAt = at;
    rerun();
  });
  $("reset").addEventListener("click", () => { presses.reset = +now.toFixed(3); rerun(); });
  $("clear-buttons").addEventListener("click", () => { presses.holds = []; presses.reset = null; rerun(); });
  ["single", "dry", "bdel", "opt", "feed-ov", "rapid-ov"].forEach((id) => $(id).addEventListener("change", rerun));
  $("machine").addEventListener("change", () => { simCurrent = false; rerun(); });
  $("params").addEventListener("change", rerun);
  $("stock").addEventListener("change", () => { partCache = null; fitted && fit(); draw(); });
  $("run").addEventListener("click", run);
  $("view").addEventListener("change", () => { view.kind = $("view").value; fit(); draw(); });
  $("lang").addEventListener("click", () => { lang = lang === "zh" ? "en" : "zh"; applyWords(); if (S) { showProblems(); showTime(); showParams(); showPasses(); legend(); setTime(now, false); } showPresses(); });

  // ---- zoom, pan, pick ------------------------------------------------------------------------
  function zoom(k, cx, cy) {
    const x = cx === undefined ? cw / 2 : cx, y = cy === undefined ? ch / 2 : cy;
    const u = view.ou + x / view.s, v = view.ov + (ch - y) / view.s;
    // Bounded: far past a micrometre per screen the grid's steps would stop adding up.
    view.s = Math.min(1e5, Math.max(1e-4, view.s * k));
    view.ou = u - x / view.s; view.ov = v - (ch - y) / view.s;
    fitted = false;
    draw();
  }
  canvas.addEventListener("wheel", (e) => { e.preventDefault(); const r = canvas.getBoundingClientRect(); zoom(e.deltaY < 0 ? 1.25 : 0.8, e.clientX - r.left, e.clientY - r.top); }, { passive: false });
  let drag = null;
  canvas.addEventListener("pointerdown", (e) => { drag = { x: e.clientX, y: e.clientY, ou: view.ou, ov: view.ov, moved: false }; canvas.setPointerCapture(e.pointerId); });
  canvas.addEventListener("pointermove", (e) => {
    if (drag) {
      const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
      if (Math.abs(dx) + Math.abs(dy) > 3) drag.moved = true;
      if (drag.moved) { view.ou = drag.ou - dx / view.s; view.ov = drag.ov + dy / view.s; fitted = false; draw(); }
      return;
    }
    hover(e);
  });
  canvas.addEventListener("pointerup", (e) => {
    if (drag && !drag.moved) { const r = canvas.getBoundingClientRect(); const i = pick(e.clientX - r.left, e.clientY - r.top); if (i >= 0 && S.line[i]) select(S.line[i], true); }
    drag = null;
  });
  canvas.addEventListener("pointerleave", () => { $("tip").hidden = true; });
  /** The motion nearest a point of the plot (within 8 px), or -1. */
  function pick(x, y) {
    if (!S) return -1;
    const pv = V(), A = pv.pu, B = pv.pv, p = S.p, q = [0, 0, 0];
    let best = -1, bd = 64;
    const dist2 = (ax, ay, bx, by) => { const dx = bx - ax, dy = by - ay, l = dx * dx + dy * dy; const f = l ? Math.max(0, Math.min(1, ((x - ax) * dx + (y - ay) * dy) / l)) : 0; const ex = ax + f * dx - x, ey = ay + f * dy - y; return ex * ex + ey * ey; };
    for (let i = 0; i < S.n; i++) {
      const o = 6 * i, k = S.kind[i] & 7;
      let ax = sx(A[0] * p[o] + A[1] * p[o + 1] + A[2] * p[o + 2]), ay = sy(B[0] * p[o] + B[1] * p[o + 1] + B[2] * p[o + 2]);
      const m = k === 2 || k === 4 ? 32 : 1;
      for (let s = 1; s <= m; s++) {
        let bx, by;
        if (m === 1) { bx = sx(A[0] * p[o + 3] + A[1] * p[o + 4] + A[2] * p[o + 5]); by = sy(B[0] * p[o + 3] + B[1] * p[o + 4] + B[2] * p[o + 5]); }
        else { pointAt(i, s / m, q); bx = screenX(A, q); by = screenY(B, q); }
        if (!((ax < x - 8 && bx < x - 8) || (ax > x + 8 && bx > x + 8) || (ay < y - 8 && by < y - 8) || (ay > y + 8 && by > y + 8))) {
          const d = dist2(ax, ay, bx, by);
          // Cutting moves win over rapids at the same distance.
          if (d < bd || (d <= bd && k !== 0)) { bd = d; best = i; }
        }
        ax = bx; ay = by;
      }
    }
    return best;
  }
  let hoverPending = false;
  function hover(e) {
    if (hoverPending || !S) return;
    hoverPending = true;
    requestAnimationFrame(() => {
      hoverPending = false;
      const r = canvas.getBoundingClientRect(), x = e.clientX - r.left, y = e.clientY - r.top;
      const i = S.n < 300000 ? pick(x, y) : -1;
      const tip = $("tip");
      if (i < 0) { tip.hidden = true; return; }
      const o = 6 * i, k = S.kind[i] & 7;
      const end = lathe ? "X " + (2 * S.p[o + 3]).toFixed(3) + " Z " + S.p[o + 5].toFixed(3) : "X " + S.p[o + 3].toFixed(3) + " Y " + S.p[o + 4].toFixed(3) + " Z " + S.p[o + 5].toFixed(3);
      tip.textContent = t("line") + " " + S.line[i] + ": " + t("kinds")[k] + (S.kind[i] & 32 ? " (" + t("pullout") + ")" : "") + "  T" + String(S.tool[i]).padStart(2, "0") + "\n" + end +
        (k === 1 || k === 2 ? "\nF " + S.rate[i] + " mm/min" : k >= 3 ? "\n" + t("lead") + " " + S.rate[i] + " mm" : "") + "\n" + hms(S.t0[i]) + " – " + hms(S.t[i]);
      tip.style.left = Math.min(x + 14, cw - 200) + "px"; tip.style.top = y + 14 + "px"; tip.hidden = false;
    });
  }
  $("fit").addEventListener("click", () => { fit(); draw(); });
  $("zoom-in").addEventListener("click", () => zoom(1.25));
  $("zoom-out").addEventListener("click", () => zoom(0.8));
  window.addEventListener("resize", () => { editorHeight = 0; if (fitted) fit(); draw(); paintEditor(); });
  // Keys, when not typing: space CYCLE START and pause, arrows block by block (with Shift motion
  // by motion), Home, End, T next tool, F fit, + and - zoom.
  document.addEventListener("keydown", (e) => {
    const tag = (e.target && e.target.tagName) || "";
    // Typing keys belong to the field; a button or a switch clicked a moment ago keeps the focus,
    // yet space is still the player's (it would press that button again).
    const type = tag === "INPUT" ? e.target.type : "";
    const field = tag === "TEXTAREA" || tag === "SELECT" || (tag === "INPUT" && type !== "checkbox" && type !== "button");
    if (field && !(type === "range" && e.key === " ")) return;
    const k = e.key;
    if (k === " ") { e.preventDefault(); playPause(); }
    else if (k === "ArrowRight") (e.shiftKey ? stepMotion : stepBlock)(1);
    else if (k === "ArrowLeft") (e.shiftKey ? stepMotion : stepBlock)(-1);
    else if (k === "Home") { pause(); setTime(0); }
    else if (k === "End" && S) { pause(); setTime(S.head.total_s); }
    else if (k === "t" || k === "T") nextTool();
    else if (k === "f" || k === "F") { fit(); draw(); }
    else if (k === "+" || k === "=") zoom(1.25);
    else if (k === "-") zoom(0.8);
  });

  // ---- files: open and drop; GBK text decoded as the GSK controllers write it ----------------
  function decode(bytes) {
    try { return new TextDecoder("utf-8", { fatal: true }).decode(bytes); } catch (_) { return new TextDecoder("gb18030").decode(bytes); }
  }
  function load(file) {
    file.arrayBuffer().then((b) => {
      const bytes = new Uint8Array(b), text = decode(bytes).replace(/^\uFEFF/, "");
      setProgramme(text);
      remember(bytes, programmeText());
      lastNamed = null; followNamedMachine();
      fileName = file.name;
      simCurrent = false;
      $("file-name").textContent = fileName;
      fresh = true; fitted = true; selLine = 0;
      run();
    });
  }
  $("file").addEventListener("change", (e) => { if (e.target.files[0]) load(e.target.files[0]); });
  document.addEventListener("dragover", (e) => e.preventDefault());
  document.addEventListener("drop", (e) => { e.preventDefault(); const f = e.dataTransfer && e.dataTransfer.files[0]; if (f) load(f); });

  // ---- keep the work: download, autosave with a restore, the plot as PNG and SVG, a setup sheet --
  // The programme as opened: its bytes, and how to write an edited text the same way (GBK or
  // UTF-8, CR LF line ends, a byte-order mark).
  let original = null;
  function remember(bytes, text) {
    let utf8 = true;
    try { new TextDecoder("utf-8", { fatal: true }).decode(bytes); } catch (_) { utf8 = false; }
    let crlf = false;
    for (let i = 1; i < bytes.length && !crlf; i++) crlf = bytes[i] === 10 && bytes[i - 1] === 13;
    original = { bytes, text, gbk: !utf8, crlf, bom: bytes[0] === 0xef && bytes[1] === 0xbb && bytes[2] === 0xbf };
  }
  if (JOB.original) {
    const raw = atob(JOB.original.base64), bytes = new Uint8Array(raw.length);
    for (let i = 0; i < raw.length; i++) bytes[i] = raw.charCodeAt(i);
    remember(bytes, JOB.text || "");
  } else if (JOB.text) remember(enc.encode(JOB.text), JOB.text);
  /** GBK (GB18030's two-byte part) for an edited text of a GBK file: the table is the browser's own
   * decoder run backwards, built once. Characters GBK lacks are written as "?" and counted. */
  let gbkTable = null;
  function gbkEncode(text) {
    if (!gbkTable) {
      gbkTable = new Map();
      const dec = new TextDecoder("gbk"), pair = new Uint8Array(2);
      for (let a = 0x81; a <= 0xfe; a++) for (let b = 0x40; b <= 0xfe; b++) {
        if (b === 0x7f) continue;
        pair[0] = a; pair[1] = b;
        const c = dec.decode(pair);
        if (c.length === 1 && c !== "\ufffd" && !gbkTable.has(c)) gbkTable.set(c, (a << 8) | b);
      }
    }
    const out = [];
    let missing = 0;
    for (const c of text) {
      const u = c.codePointAt(0);
      if (u < 0x80) { out.push(u); continue; }
      const g = gbkTable.get(c);
      if (g === undefined) { out.push(0x3f); missing++; } else out.push(g >> 8, g & 0xff);
    }
    return { bytes: Uint8Array.from(out), missing };
  }
  function download(bytes, name, type) {
    const url = URL.createObjectURL(new Blob([bytes], { type }));
    const a = el("a", { href: url, download: name });
    document.body.appendChild(a); a.click(); a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 10000);
  }
  const baseName = () => (fileName || "programme.nc").replace(/^.*[\\/]/, "");
  /** The programme as a file: unedited, the bytes as opened; edited, in the form it was opened in. */
  function programmeBytes() {
    const text = programmeText();
    if (original && text === original.text) return { bytes: original.bytes, missing: 0 };
    const like = original || { gbk: false, crlf: false, bom: false };
    const body = like.crlf ? text.replace(/\r?\n/g, "\r\n") : text;
    if (like.gbk) return gbkEncode(body);
    const b = enc.encode(body);
    if (!like.bom) return { bytes: b, missing: 0 };
    const out = new Uint8Array(b.length + 3);
    out.set([0xef, 0xbb, 0xbf]); out.set(b, 3);
    return { bytes: out, missing: 0 };
  }
  $("save").addEventListener("click", () => {
    const { bytes, missing } = programmeBytes();
    download(bytes, baseName(), "text/plain");
    if (missing) banner("warning", t("gbk_missing", { n: missing }));
    // Saved: the autosave has done its work.
    try { localStorage.removeItem(autosaveKey()); } catch (_) {}
  });
  // Autosave: the edited text is kept in the browser (per file name) a second after typing
  // stops; opening the page again offers it back, visibly, never silently.
  const autosaveKey = () => "ncsight.autosave:" + (fileName || "(new)");
  let autosaveTimer = 0;
  ta.addEventListener("input", () => {
    clearTimeout(autosaveTimer);
    autosaveTimer = setTimeout(() => {
      try {
        if (original && programmeText() === original.text) localStorage.removeItem(autosaveKey());
        else localStorage.setItem(autosaveKey(), JSON.stringify({ text: programmeText(), at: Date.now(), machine: $("machine").value }));
      } catch (_) { /* storage full or off: nothing kept, nothing lost */ }
    }, 1000);
  });
  function offerRestore() {
    let kept = null;
    try { kept = JSON.parse(localStorage.getItem(autosaveKey()) || "null"); } catch (_) {}
    if (!kept || typeof kept.text !== "string" || kept.text === programmeText()) return;
    $("restore-text").textContent = t("restore", { file: fileName || t("newfile"), at: new Date(kept.at).toLocaleString(lang === "zh" ? "zh-CN" : "en-GB") });
    $("restore").hidden = false;
    $("restore-yes").onclick = () => {
      $("restore").hidden = true;
      setProgramme(kept.text);
      if (kept.machine && [...$("machine").options].some((o) => o.value === kept.machine)) $("machine").value = kept.machine;
      lastNamed = namedMachine(kept.text);
      simCurrent = false; fresh = true; fitted = true;
      paintEditor(); run();
    };
    $("restore-no").onclick = () => { $("restore").hidden = true; try { localStorage.removeItem(autosaveKey()); } catch (_) {} };
  }
  /** The plot as the screen shows it (PNG), or as lines (SVG: the same view, cuts in their tool's
   * colour, rapids dashed, pull-outs purple, true arcs in chords). */
  $("export-png").addEventListener("click", () => {
    const gl = G.renderer && !$("gl-box").hidden ? G.renderer.domElement : null;
    if (gl) glRender();
    (gl || canvas).toBlob((b) => b && b.arrayBuffer().then((a) => download(new Uint8Array(a), baseName().replace(/\.[^.]*$/, "") + ".png", "image/png")), "image/png");
  });
  $("export-svg").addEventListener("click", () => download(enc.encode(plotSvg()), baseName().replace(/\.[^.]*$/, "") + ".svg", "image/svg+xml"));
  function plotSvg() {
    const xml = (v) => String(v).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;").replace(/"/g, "&quot;");
    const out = [`<svg xmlns="http://www.w3.org/2000/svg" width="${cw}" height="${ch}" viewBox="0 0 ${cw} ${ch}">`, `<rect width="${cw}" height="${ch}" fill="#fff"/>`];
    out.push(`<title>${xml(baseName() + " — " + (S ? S.head.title : ""))}</title>`);
    if (S && S.n) {
      const pv = V(), A = pv.pu, B = pv.pv, q = [0, 0, 0];
      const runs = new Map(); // style -> path data
      for (let i = 0; i < S.n; i++) {
        const k = S.kind[i] & 7, m = k === 2 || k === 4 ? 24 : 1;
        let d = "";
        for (let j = 0; j <= m; j++) { pointAt(i, j / m, q); d += (j ? "L" : "M") + screenX(A, q).toFixed(1) + " " + screenY(B, q).toFixed(1); }
        const st = S.style[i];
        runs.set(st, (runs.get(st) || "") + d);
      }
      runs.forEach((d, st) => {
        const colour = st === 0 ? "#9e9e9e" : st === 1 ? "#8e24aa" : toolColour(S.tools[Math.floor((st - 2) / 2) - 1]);
        out.push(`<path d="${d}" fill="none" stroke="${colour}" stroke-width="${st % 2 && st > 1 ? 2.2 : 1.3}"${st === 0 ? ' stroke-dasharray="4 3"' : ""}/>`);
      });
    }
    out.push(`<text x="8" y="${ch - 8}" font-family="sans-serif" font-size="12" fill="#37474f">${xml(baseName() + " · " + (S ? S.head.machine : "") + " · " + t("view_" + view.kind))}</text>`, "</svg>");
    return out.join("\n");
  }
  /** Per tool: its motions' time by kind, the extents of its cutting moves, its feeds, leads and
   * spindle speeds, the line that called it. */
  function toolSheet() {
    const rows = new Map();
    const row = (tool) => {
      if (!rows.has(tool)) rows.set(tool, { tool, line: 0, time: [0, 0, 0, 0], min: [Infinity, Infinity, Infinity], max: [-Infinity, -Infinity, -Infinity], feed: [Infinity, 0], lead: new Set(), rpm: [Infinity, 0], total: 0 });
      return rows.get(tool);
    };
    let rpm = 0, e = 0;
    const ev = S.head.events;
    for (let i = 0; i < S.n; i++) {
      while (e < ev.length && ev[e].seg <= i) { const x = ev[e++]; if (x.k === "spindle") rpm = Math.abs(x.rpm); if (x.k === "tool" && !row(x.tool).line) row(x.tool).line = x.l; }
      const r = row(S.tool[i]), k = S.kind[i] & 7, d = S.t[i] - S.t0[i];
      r.time[Math.min(k, 3)] += d; r.total += d;
      if (k === 0) continue;
      const o = 6 * i;
      for (let a = 0; a < 3; a++) { const v = a === 0 && lathe ? 2 : 1; r.min[a] = Math.min(r.min[a], v * S.p[o + a], v * S.p[o + 3 + a]); r.max[a] = Math.max(r.max[a], v * S.p[o + a], v * S.p[o + 3 + a]); }
      if (k >= 3) r.lead.add(S.rate[i]); else { r.feed[0] = Math.min(r.feed[0], S.rate[i]); r.feed[1] = Math.max(r.feed[1], S.rate[i]); }
      if (rpm) { r.rpm[0] = Math.min(r.rpm[0], rpm); r.rpm[1] = Math.max(r.rpm[1], rpm); }
    }
    return [...rows.values()];
  }
  /** The setup sheet: the programme, its controller and time, the plot, and a row per tool; printed
   * alone (the page's print style shows only it). */
  function setupSheet() {
    const box = $("sheet");
    box.textContent = "";
    if (!S) return box;
    const range = (a, b, f) => (a > b ? "-" : a === b ? f(a) : f(a) + " – " + f(b));
    const mm = (v) => numLabel(+v.toFixed(3));
    box.appendChild(el("h2", {}, t("sheet") + ": " + baseName()));
    box.appendChild(el("div", {}, S.head.title + " · " + t("total") + " " + hms(S.head.total_s) + " · " + new Date().toLocaleString(lang === "zh" ? "zh-CN" : "en-GB")));
    const img = el("img", { alt: t("view_" + view.kind), src: canvas.toDataURL("image/png") });
    img.className = "sheet-plot";
    box.appendChild(img);
    const tb = el("table", { id: "sheet-tools" });
    const head = el("tr");
    ["sh_tool", "sh_name", "line", lathe ? "sh_xz" : "sh_xyz", "sh_feed", "sh_speed", "sh_cut", "rapid", "total"].forEach((k) => head.appendChild(el("th", {}, t(k))));
    tb.appendChild(head);
    toolSheet().forEach((r) => {
      const tr = el("tr");
      const ext = lathe ? "X Ø " + range(r.min[0], r.max[0], mm) + ", Z " + range(r.min[2], r.max[2], mm) : ["X", "Y", "Z"].map((a, j) => a + " " + range(r.min[j], r.max[j], mm)).join(", ");
      // On a lathe the feed per revolution too, where the spindle speed was one.
      const perRev = lathe && r.rpm[1] && r.rpm[0] === r.rpm[1] && r.feed[1] ? " (" + range(r.feed[0] / r.rpm[0], r.feed[1] / r.rpm[0], (v) => numLabel(+v.toFixed(3))) + " mm/r)" : "";
      const feeds = [r.feed[1] ? range(r.feed[0], r.feed[1], (v) => numLabel(+v.toFixed(1))) + " mm/min" + perRev : "", r.lead.size ? t("lead") + " " + [...r.lead].map((v) => numLabel(+v.toFixed(4))).join(", ") + " mm" : ""].filter(Boolean).join("; ");
      [["T" + String(r.tool).padStart(2, "0")], [toolName(r.tool)], [r.line || "-"], [ext], [feeds || "-"], [r.rpm[1] ? range(r.rpm[0], r.rpm[1], (v) => Math.round(v)) + " rpm" : "-"], [hms(r.time[1] + r.time[2] + r.time[3]), "num"], [hms(r.time[0]), "num"], [hms(r.total), "num"]].forEach(([v, cls]) => tr.appendChild(el("td", cls ? { class: cls } : {}, v)));
      tb.appendChild(tr);
    });
    box.appendChild(tb);
    // The time by operation (rapid, feed, arc, thread, dwell, tool changes), as the Time panel.
    const ops = $("time-by-op");
    if (ops) { const copy = ops.cloneNode(true); copy.id = "sheet-ops"; box.appendChild(copy); }
    box.appendChild(el("div", { class: "sheet-note" }, t("sheet_note")));
    return box;
  }
  $("print-sheet").addEventListener("click", () => { setupSheet(); window.print(); });
  window.addEventListener("beforeprint", setupSheet);

  // ---- port to another controller (ncsight port, in the engine): the two programmes side by
  // side, the ported one's path overlaid on the plot, the differences listed ----------------
  let portScene = null, ported = null;
  function fillPortTargets() {
    const sel = $("port-to"), keep = sel.value;
    while (sel.firstChild) sel.removeChild(sel.firstChild);
    JOB.machines.filter((m) => m[2] === lathe && m[0] !== $("machine").value).forEach((m) => sel.appendChild(el("option", { value: m[0] }, m[0])));
    if ([...sel.options].some((o) => o.value === keep)) sel.value = keep;
  }
  async function portTo() {
    const to = $("port-to").value, from = $("machine").value;
    if (!to) return;
    await settled();
    const text = programmeText();
    const buf = await callEngine("ncsight_port", enc.encode(text), from, $("params").value, JOB.setup || "", "to=" + to);
    const answer = new TextDecoder().decode(new Uint8Array(buf));
    const status = $("port-status"), list = $("port-list");
    list.textContent = "";
    if (answer.startsWith("NCSE")) { status.className = "alarm"; status.textContent = answer.slice(4); return; }
    const P = JSON.parse(answer);
    if (P.alarm) {
      status.className = "alarm"; status.textContent = t("port_alarm", { from, line: P.alarm.line });
      list.appendChild(el("div", { class: "p alarm" }, P.alarm.message));
      ported = null; portScene = null; $("port-save").disabled = true; draw();
      return;
    }
    ported = P;
    status.className = P.exact ? "ok" : "approx";
    status.textContent = t(P.exact ? "port_exact" : "port_approx", { to, n: P.rewritten.length, d: P.differences.length });
    const item = (cls, line, text) => { const d = el("div", { class: "p " + cls, "data-line": line }, text); d.addEventListener("click", () => line && select(line, true)); list.appendChild(d); };
    P.differences.forEach((d) => item("alarm", d.line, t("port_diff", { line: d.line, what: d.what, size: +Number(d.size).toFixed(4) })));
    P.rewritten.forEach((r) => item("warning", r.line, t("port_rewritten", { line: r.line, why: r.why })));
    $("port-from").textContent = text;
    $("port-text").textContent = P.text;
    $("port-save").disabled = false;
    // The ported programme run on its controller: its path over the original's.
    const sb = await callEngine("ncsight_scene", enc.encode(P.text), to, "", "", "");
    const scene = parseScene(sb);
    portScene = scene.usage ? null : scene;
    draw();
  }
  /** The ported programme's path, a wide orange band under the original's: where they agree the
   * original's line runs inside it; where they differ the band stands alone. */
  function drawPorted(A, B) {
    if (!portScene || !$("port-overlay").checked) return;
    const P = portScene.p;
    ctx.strokeStyle = "rgba(255,111,0,0.45)"; ctx.lineWidth = 6; ctx.lineCap = "round";
    ctx.beginPath();
    for (let i = 0; i < portScene.n; i++) {
      if ((portScene.kind[i] & 7) === 0) continue;
      const o = 6 * i;
      ctx.moveTo(sx(A[0] * P[o] + A[1] * P[o + 1] + A[2] * P[o + 2]), sy(B[0] * P[o] + B[1] * P[o + 1] + B[2] * P[o + 2]));
      ctx.lineTo(sx(A[0] * P[o + 3] + A[1] * P[o + 4] + A[2] * P[o + 5]), sy(B[0] * P[o + 3] + B[1] * P[o + 4] + B[2] * P[o + 5]));
    }
    ctx.stroke(); ctx.lineCap = "butt";
  }
  $("port-run").addEventListener("click", portTo);
  $("port-overlay").addEventListener("change", draw);
  $("port-save").addEventListener("click", () => ported && download(enc.encode(ported.text), baseName().replace(/\.[^.]*$/, "") + "-" + ported.to + ".nc", "text/plain"));

  // ---- the thread passes, unrolled: the long axis across, the spindle angle down ------------
  // Each pass is the line the tool's point follows on the surface, in its own colour: passes that
  // line up lie on each other; a split thread (a pass out of phase) shows as a second line.
  const PASS_COLOURS = ["#1565c0", "#d84315", "#2e7d32", "#6a1b9a", "#00838f", "#ef6c00", "#ad1457", "#5d4037"];
  function showPasses() {
    const box = $("passes-box");
    // Along the axis that moves more in each pass (Z for most threads, X for a face thread); the
    // passes along the axis of the first one are drawn.
    const along = (i) => { const o = 6 * i; return Math.abs(S.p[o + 5] - S.p[o + 2]) >= Math.abs(S.p[o + 3] - S.p[o]) ? 2 : 0; };
    const all = S.head.threads.filter((r) => !(S.kind[r[0]] & 32));
    const threads = all.filter((r) => along(r[0]) === along(all.length ? all[0][0] : 0));
    box.hidden = !threads.length;
    if (!threads.length) return;
    const c = $("passes"), g = c.getContext("2d"), W = c.width, Hc = c.height;
    const faceX = along(threads[0][0]) === 0; // X across, labelled as a diameter
    let a0 = Infinity, a1 = -Infinity;
    threads.forEach((r) => { const o = 6 * r[0], ax = along(r[0]); a0 = Math.min(a0, S.p[o + ax], S.p[o + 3 + ax]); a1 = Math.max(a1, S.p[o + ax], S.p[o + 3 + ax]); });
    if (!(a1 > a0)) { box.hidden = true; return; }
    const L = 50, R = 20, T = 24, B = 44;
    const X = (a) => L + (a - a0) / (a1 - a0) * (W - L - R), Y = (deg) => T + deg / 360 * (Hc - T - B);
    g.fillStyle = "#fff"; g.fillRect(0, 0, W, Hc);
    g.strokeStyle = "#dde2e7"; g.lineWidth = 1; g.fillStyle = "#37474f"; g.font = "11px system-ui,sans-serif";
    g.textAlign = "right"; g.textBaseline = "middle";
    for (let d = 0; d <= 360; d += 90) { g.beginPath(); g.moveTo(L, Y(d)); g.lineTo(W - R, Y(d)); g.stroke(); g.fillText(d + "°", L - 4, Y(d)); }
    const step = niceStep((a1 - a0) / 8);
    g.textAlign = "center"; g.textBaseline = "top";
    for (let a = Math.ceil(a0 / step) * step; a <= a1 + 1e-9; a += step) { g.beginPath(); g.moveTo(X(a), T); g.lineTo(X(a), Hc - B); g.stroke(); g.fillText(numLabel(faceX ? 2 * a : a), X(a), Hc - B + 4); }
    g.textAlign = "left"; g.fillText(faceX ? "X Ø mm" : "Z mm", W - R - 40, Hc - 16);
    g.textBaseline = "top"; g.fillText(t("passes_axis"), 4, 4);
    const passes = new Set();
    threads.forEach((r) => {
      const i = r[0], o = 6 * i, ax = along(i), lead = S.rate[i];
      if (!(lead > 0)) return;
      const from = S.p[o + ax], to = S.p[o + 3 + ax];
      g.strokeStyle = PASS_COLOURS[(r[3] - 1) % PASS_COLOURS.length]; g.lineWidth = 1.6;
      passes.add(r[3]);
      // The angle grows by 360 degrees per lead along the axis; the line wraps at 360 (each
      // turn drawn whole, at most 5000 turns a pass).
      const turns = Math.abs(to - from) / lead, at = (f) => from + (to - from) * f;
      g.beginPath();
      let f = 0, ang = ((r[1] % 360) + 360) % 360;
      for (let k = 0; f < 1 - 1e-12 && k < 5000; k++) {
        const fNext = turns > 0 ? Math.min(1, f + (360 - ang) / (360 * turns)) : 1;
        g.moveTo(X(at(f)), Y(ang));
        g.lineTo(X(at(fNext)), Y(ang + 360 * turns * (fNext - f)));
        f = fNext; ang = 0;
      }
      g.stroke();
    });
    // The legend along the bottom.
    let x = L;
    [...passes].sort((a, b) => a - b).slice(0, 10).forEach((p) => { g.fillStyle = PASS_COLOURS[(p - 1) % PASS_COLOURS.length]; g.fillRect(x, Hc - 12, 14, 3); g.fillStyle = "#37474f"; g.fillText(t("pass", { n: p }), x + 18, Hc - 16); x += 76; });
  }

  // ---- the thread from the stock simulation (ncsight report --stock) ---------------------------
  function showThread() {
    if (!JOB.sim && !JOB.sim_error) return;
    $("thread-box").hidden = false;
    $("thread-box").open = true;
    const th = $("thread");
    th.appendChild(el("div", {}, t("threadtitle")));
    if (!JOB.sim) { th.appendChild(el("p", { class: "notice" }, "The thread could not be simulated on the stock: " + JOB.sim_error)); return; }
    const m = JOB.sim, f = (v) => (v === null || v === undefined ? "-" : Number(v).toFixed(3));
    const tb = el("table");
    [["major diameter", f(m.major_diameter_mm) + " mm"], ["minor diameter", f(m.minor_diameter_mm) + " mm"], ["depth", f(m.depth_mm) + " mm"], ["pitch", f(m.pitch_mm) + " mm"], ["lead", f(m.lead_mm) + " mm"],
     ["starts", m.starts === null ? "-" : String(m.starts)], ["flank angles", m.flank_angles_deg ? m.flank_angles_deg[0].toFixed(1) + " + " + m.flank_angles_deg[1].toFixed(1) + " deg" : "-"],
     ["full-depth length", f(m.full_depth_length_mm) + " mm"], ["run-out length", f(m.runout_length_mm) + " mm"]].forEach((r) => { const tr = el("tr"); tr.appendChild(el("th", {}, r[0])); tr.appendChild(el("td", {}, r[1])); tb.appendChild(tr); });
    th.appendChild(tb);
    if (JOB.section && JOB.section.length > 1) th.appendChild(threadSection(m));
    if (JOB.unrolled) { th.appendChild(el("div", {}, t("unrolled"))); th.appendChild(el("img", { src: JOB.unrolled, alt: "unrolled thread surface" })); }
    const ul = el("ul");
    (m.findings || []).forEach((x) => ul.appendChild(el("li", {}, x.kind + (x.line ? " (line " + x.line + ")" : "") + ": " + x.message)));
    if (!(m.findings || []).length) ul.appendChild(el("li", {}, "no findings"));
    th.appendChild(ul);
  }

  /** The axial section at 0 degrees, true scale, cropped to a few pitches in the middle of the
   * thread, with the nominal profile of --expect over it and the measured major and minor
   * diameters and pitch dimensioned. */
  function threadSection(m) {
    const W = 900, Hc = 300;
    const c = el("canvas", { id: "thread-section", width: W, height: Hc, role: "img", "aria-label": "axial section" });
    const g = c.getContext("2d");
    const sec = JOB.section;
    if (!(m.major_diameter_mm > 0 && m.minor_diameter_mm > 0)) return el("div", {}, "-");
    // The thread's length: where the section goes below the middle of its depth (a turned
    // shank beside it stays above).
    const half = (m.major_diameter_mm + m.minor_diameter_mm) / 2;
    const deep = sec.filter((p) => p[1] < half);
    if (deep.length < 2) return el("div", {}, "-");
    const cut = sec.filter((p) => p[0] >= deep[0][0] && p[0] <= deep[deep.length - 1][0]);
    const P = m.pitch_mm || (JOB.expect && JOB.expect.pitch_mm) || (cut[cut.length - 1][0] - cut[0][0]) / 4;
    const zMid = (cut[0][0] + cut[cut.length - 1][0]) / 2, span = Math.min(cut[cut.length - 1][0] - cut[0][0], 4 * P);
    const z0 = zMid - span / 2, z1 = zMid + span / 2;
    c.setAttribute("data-z0", z0.toFixed(3)); c.setAttribute("data-z1", z1.toFixed(3));
    const major = m.major_diameter_mm / 2, minor = m.minor_diameter_mm / 2, h = Math.max(major - minor, 1e-3);
    const r0 = minor - 0.6 * h, r1 = major + 0.9 * h;
    const s = Math.min((W - 140) / (z1 - z0), (Hc - 50) / (r1 - r0));
    const X = (z) => 60 + (z - z0) * s, Y = (r) => Hc - 30 - (r - r0) * s;
    g.fillStyle = "#fff"; g.fillRect(0, 0, W, Hc);
    // The metal: below the section line.
    g.beginPath(); g.moveTo(X(z0), Y(r0));
    sec.forEach((p) => { if (p[0] >= z0 && p[0] <= z1) g.lineTo(X(p[0]), Y(p[1] / 2)); });
    g.lineTo(X(z1), Y(r0)); g.closePath();
    g.fillStyle = "#b0bec5"; g.fill(); g.strokeStyle = "#37474f"; g.lineWidth = 1.5; g.stroke();
    // The nominal profile: flanks at 60 degrees between the expected major and minor, crest and
    // root flats in the ISO proportion (1 : 2), a root placed on the deepest point measured.
    if (JOB.expect && JOB.expect.pitch_mm > 0) {
      const E = JOB.expect, R = E.major_mm / 2, r = E.minor_mm / 2, f = (R - r) * Math.tan(Math.PI / 6), rest = Math.max(0, E.pitch_mm - 2 * f);
      // The measured root nearest the middle: the centre of the run of its deepest points.
      let deepest = Infinity;
      cut.forEach((p) => { if (Math.abs(p[0] - zMid) < E.pitch_mm / 2 && p[1] < deepest) deepest = p[1]; });
      const bottom = cut.filter((p) => Math.abs(p[0] - zMid) < E.pitch_mm / 2 && p[1] < deepest + 1e-3);
      const rootZ = bottom.length ? (bottom[0][0] + bottom[bottom.length - 1][0]) / 2 : zMid;
      const root = rest * 2 / 3, crest = rest / 3;
      g.save(); g.beginPath(); g.rect(X(z0), 0, X(z1) - X(z0), Hc); g.clip();
      g.strokeStyle = "#d32f2f"; g.setLineDash([6, 4]); g.lineWidth = 1.5; g.beginPath();
      let z = rootZ - root / 2 - Math.ceil((rootZ - z0) / E.pitch_mm + 1) * E.pitch_mm;
      g.moveTo(X(z), Y(r));
      while (z < z1 + E.pitch_mm) {
        g.lineTo(X(z + root), Y(r)); g.lineTo(X(z + root + f), Y(R)); g.lineTo(X(z + root + f + crest), Y(R)); g.lineTo(X(z + E.pitch_mm), Y(r));
        z += E.pitch_mm;
      }
      g.stroke(); g.setLineDash([]); g.restore();
    }
    // Dimensions: the measured major and minor diameters, the pitch.
    g.fillStyle = "#00695c"; g.strokeStyle = "#00695c"; g.lineWidth = 1; g.font = "12px system-ui,sans-serif"; g.textBaseline = "bottom";
    [[major, "Ø " + m.major_diameter_mm.toFixed(3)], [minor, "Ø " + m.minor_diameter_mm.toFixed(3)]].forEach(([r, label]) => {
      g.setLineDash([2, 3]); g.beginPath(); g.moveTo(X(z0), Y(r)); g.lineTo(X(z1) + 10, Y(r)); g.stroke(); g.setLineDash([]);
      g.fillText(label, X(z1) + 12, Y(r) + 6);
    });
    if (m.pitch_mm) {
      const y = Y(r1) + 14, a = X(zMid - P / 2), b = X(zMid + P / 2);
      g.beginPath(); g.moveTo(a, y); g.lineTo(b, y); g.moveTo(a, y - 5); g.lineTo(a, y + 5); g.moveTo(b, y - 5); g.lineTo(b, y + 5); g.stroke();
      g.textAlign = "center"; g.fillText("P " + m.pitch_mm.toFixed(3) + (m.flank_angles_deg ? "   " + m.flank_angles_deg[0].toFixed(1) + "° + " + m.flank_angles_deg[1].toFixed(1) + "°" : ""), (a + b) / 2, y - 3); g.textAlign = "left";
    }
    g.fillStyle = "#37474f"; g.textBaseline = "top";
    g.fillText(t("section") + (JOB.expect ? "  — " + t("nominal") + " " + JOB.expect.name : ""), 8, 6);
    g.fillText("Z " + z0.toFixed(2) + " … " + z1.toFixed(2) + " mm", 8, Hc - 18);
    return c;
  }

  // ---- the cut stock in 3D: the engine's stock simulation drawn with three.js ------------------
  // The engine cuts the stock (`ncsight_stock`) up to the player's time and answers its grid: a
  // lathe's outer and inner radius per angle and Z, a mill's top per X and Y. It is drawn as a
  // lit mesh: the turned part with the quarter toward the viewer cut away to show its inside
  // (the section in orange), the mill block grey where untouched, blue where cut. The tool and its holder are drawn
  // where the player is, the simulation's findings as red balls. Drag turns the view, the wheel
  // zooms. While the programme plays the stock is cut again each time the engine is free.
  const G = { renderer: null, scene: null, camera: null, part: null, marks: null, tool: null, toolKey: "", fail: null, data: null, key: "", busy: false, want: null, yaw: 0.6, pitch: 0.45, dist: 0, target: [0, 0, 0] };
  const is3d = () => view.kind === "cut3d";
  const SECTION = 0xe0822a;
  function glInit() {
    if (G.renderer || G.fail) return !!G.renderer;
    try {
      const c = el("canvas", { id: "gl" });
      const renderer = new THREE.WebGLRenderer({ canvas: c, antialias: true, preserveDrawingBuffer: true });
      if (!renderer.getContext()) throw new Error("no WebGL context");
      G.renderer = renderer;
      G.scene = new THREE.Scene();
      G.scene.background = new THREE.Color(0xf4f6f8);
      G.scene.add(new THREE.HemisphereLight(0xffffff, 0x8090a0, 1.6));
      const sun = new THREE.DirectionalLight(0xffffff, 1.8);
      sun.position.set(1, 2, 3);
      G.camera = new THREE.PerspectiveCamera(35, 1, 0.1, 1e5);
      G.camera.add(sun);
      G.scene.add(G.camera);
      $("gl-box").appendChild(c);
      let drag = null;
      c.addEventListener("pointerdown", (e) => { drag = [e.clientX, e.clientY]; c.setPointerCapture(e.pointerId); });
      c.addEventListener("pointermove", (e) => {
        if (!drag) return;
        G.yaw -= (e.clientX - drag[0]) * 0.01; G.pitch = Math.max(-1.5, Math.min(1.5, G.pitch + (e.clientY - drag[1]) * 0.01));
        drag = [e.clientX, e.clientY]; glRender();
      });
      c.addEventListener("pointerup", () => { drag = null; });
      c.addEventListener("wheel", (e) => { e.preventDefault(); G.dist *= e.deltaY > 0 ? 1.15 : 1 / 1.15; glRender(); }, { passive: false });
      return true;
    } catch (e) {
      G.fail = String((e && e.message) || e);
      return false;
    }
  }
  /** Show the 3D view (the 2D canvas hidden) and ask the engine for the stock at the player's time. */
  function draw3d() {
    canvas.hidden = true;
    $("gl-box").hidden = false;
    if (!glInit()) { $("gl-note").textContent = t("gl_none") + " (" + G.fail + ")"; return; }
    glRender();
    requestStock();
  }
  function hide3d() { canvas.hidden = false; $("gl-box").hidden = true; }
  /** One request at a time: a newer time waits for the answer before it, then asks once. */
  function requestStock() {
    if (!S) return;
    const whole = now >= S.head.total_s - 1e-9;
    const want = { text: programmeText(), machine: $("machine").value, params: $("params").value, options: optionsText(), stock: $("stock").value.trim(), until: whole ? null : now };
    const key = JSON.stringify(want);
    if (key === G.key) return;
    if (G.busy) { G.want = want; return; }
    G.busy = true; G.key = key; G.want = null;
    if (!G.data) $("gl-note").textContent = t("gl_wait");
    const opts = want.options + "\nstock=" + want.stock + (want.until === null ? "" : "\nuntil_s=" + want.until);
    callEngine("ncsight_stock", enc.encode(want.text), want.machine, want.params, JOB.setup || "", opts).then((buf) => {
      G.busy = false;
      const d = parseStock(buf);
      if (d.usage) { G.data = null; glClear(); $("gl-note").textContent = d.usage; }
      else { const first = !G.data || G.data.head.kind !== d.head.kind; G.data = d; glBuild(d, first); $("gl-note").textContent = glNote(d); }
      glRender();
      if (G.want && is3d()) { G.key = ""; requestStock(); }
    }, (e) => { G.busy = false; G.key = ""; if (e !== CANCELLED) $("gl-note").textContent = String((e && e.message) || e); else if (is3d()) requestStock(); });
  }
  function parseStock(buf) {
    const u8 = new Uint8Array(buf);
    if (String.fromCharCode(u8[0], u8[1], u8[2], u8[3]) === "NCSE") return { usage: new TextDecoder().decode(u8.subarray(4)) };
    const jl = new DataView(buf).getUint32(4, true);
    const head = JSON.parse(new TextDecoder().decode(u8.subarray(8, 8 + jl)));
    const at = Math.ceil((8 + jl) / 4) * 4;
    if (head.kind === "lathe") {
      const n = head.nz * head.ntheta;
      return { head, outer: new Float32Array(buf, at, n), inner: new Float32Array(buf, at + 4 * n, n) };
    }
    return { head, top: new Float32Array(buf, at, head.nx * head.ny) };
  }
  function glNote(d) {
    const h = d.head, f = h.findings.filter((x) => x.kind !== "not_simulated").length;
    const size = h.kind === "lathe" ? "Ø" + h.diameter_mm + " × " + h.length_mm + " mm" + (h.guessed ? " (" + t("stockguess") + ")" : "") : (h.nx * h.cell_mm).toFixed(1) + " × " + (h.ny * h.cell_mm).toFixed(1) + " × " + (h.top_mm - h.bottom_mm).toFixed(1) + " mm";
    return size + (f ? " · " + t("findings", { n: f }) : "") + (h.until_s !== null ? " · t = " + hms(h.until_s) : "");
  }
  function glClear() {
    for (const k of ["part", "marks"]) if (G[k]) { G.scene.remove(G[k]); G[k].traverse((o) => { if (o.geometry) o.geometry.dispose(); if (o.material) o.material.dispose(); }); G[k] = null; }
  }
  /** A mesh of quads: `quad(a, b, c, d)` over vertices added by `vertex(x, y, z, colour)`. */
  function meshBuilder() {
    const pos = [], col = [], idx = [];
    return {
      vertex(x, y, z, c) { pos.push(x, y, z); col.push(((c >> 16) & 255) / 255, ((c >> 8) & 255) / 255, (c & 255) / 255); return pos.length / 3 - 1; },
      quad(a, b, c, d) { idx.push(a, b, c, a, c, d); },
      mesh() {
        const g = new THREE.BufferGeometry();
        g.setAttribute("position", new THREE.Float32BufferAttribute(pos, 3));
        g.setAttribute("color", new THREE.Float32BufferAttribute(col, 3));
        g.setIndex(idx);
        g.computeVertexNormals();
        return new THREE.Mesh(g, new THREE.MeshStandardMaterial({ vertexColors: true, side: THREE.DoubleSide, roughness: 0.55, metalness: 0.25 }));
      },
    };
  }
  /** The turned part, the spindle axis along three's x (the chuck on the left): every angle but
   * the quarter toward the viewer (y > 0, z > 0), its outside, its bore, its ends, and the two
   * faces of the cut-away in the section's colour. */
  function latheMesh(d) {
    const h = d.head, nz = h.nz, nt = h.ntheta, B = meshBuilder(), q0 = nt / 4;
    const ang = (j) => (2 * Math.PI * j) / nt;
    const R = (a, j, i) => a[(j % nt) * nz + i];
    const solid = (j, i) => R(d.outer, j, i) > R(d.inner, j, i) + 1e-4;
    // One surface (outer or inner) over angles q0..nt (the quarter 0..q0 is cut away).
    const surface = (a, colour) => {
      const id = [];
      for (let j = q0; j <= nt; j++) { const row = []; for (let i = 0; i < nz; i++) { const r = Math.max(R(a, j, i), 0); row.push(B.vertex(h.z0_mm + i * h.dz_mm, r * Math.cos(ang(j)), r * Math.sin(ang(j)), colour)); } id.push(row); }
      for (let j = 0; j < id.length - 1; j++) for (let i = 0; i < nz - 1; i++) if (solid(j + q0, i) && solid(j + q0, i + 1)) B.quad(id[j][i], id[j][i + 1], id[j + 1][i + 1], id[j + 1][i]);
    };
    surface(d.outer, 0xb8c4cc);
    surface(d.inner, 0x8d9aa3);
    // The cut-away's faces at angle 0 and 90 degrees: from the bore to the outside, per Z cell.
    for (const j of [0, q0]) {
      const c = Math.cos(ang(j)), s = Math.sin(ang(j));
      for (let i = 0; i < nz - 1; i++) {
        if (!solid(j, i) || !solid(j, i + 1)) continue;
        const z = h.z0_mm + i * h.dz_mm, z1 = z + h.dz_mm;
        const a = B.vertex(z, R(d.inner, j, i) * c, R(d.inner, j, i) * s, SECTION), b = B.vertex(z1, R(d.inner, j, i + 1) * c, R(d.inner, j, i + 1) * s, SECTION);
        const e = B.vertex(z1, R(d.outer, j, i + 1) * c, R(d.outer, j, i + 1) * s, SECTION), f = B.vertex(z, R(d.outer, j, i) * c, R(d.outer, j, i) * s, SECTION);
        B.quad(a, b, e, f);
      }
    }
    // The ends (the chuck's and the face): rings from the bore to the outside.
    for (const i of [0, nz - 1]) {
      for (let j = q0; j < nt; j++) {
        if (!solid(j, i)) continue;
        const z = h.z0_mm + i * h.dz_mm, p = (jj, a) => B.vertex(z, R(a, jj, i) * Math.cos(ang(jj)), R(a, jj, i) * Math.sin(ang(jj)), 0xcfd8dc);
        B.quad(p(j, d.inner), p(j + 1, d.inner), p(j + 1, d.outer), p(j, d.outer));
      }
    }
    return B.mesh();
  }
  /** The mill block: its top as cut (coloured from the top's grey to deep blue at the bottom),
   * its four sides and its bottom. Machine X, Y, Z are three's x, -z, y. */
  function millMesh(d) {
    const h = d.head, nx = h.nx, ny = h.ny, B = meshBuilder(), c = h.cell_mm;
    const depth = Math.max(h.top_mm - h.bottom_mm, 1e-6);
    // The untouched top grey; what is cut blue, light near the top, deep at the bottom.
    const shade = (z) => {
      if (z >= h.top_mm - 1e-3) return 0xc8d0d6;
      const u = Math.max(0, Math.min(1, (h.top_mm - z) / depth)), mix = (a, b) => Math.round(a + (b - a) * Math.sqrt(u));
      return (mix(0x5c, 0x0d) << 16) | (mix(0x9c, 0x3c) << 8) | mix(0xe0, 0x8c);
    };
    const X = (i) => h.x0_mm + (i + 0.5) * c, Y = (j) => h.y0_mm + (j + 0.5) * c;
    const top = (i, j) => d.top[j * nx + i];
    const id = new Int32Array(nx * ny);
    for (let j = 0; j < ny; j++) for (let i = 0; i < nx; i++) id[j * nx + i] = B.vertex(X(i), top(i, j), -Y(j), shade(top(i, j)));
    for (let j = 0; j < ny - 1; j++) for (let i = 0; i < nx - 1; i++) B.quad(id[j * nx + i], id[j * nx + i + 1], id[(j + 1) * nx + i + 1], id[(j + 1) * nx + i]);
    // The sides: the top's edge down to the bottom.
    const side = (pts) => { for (let k = 0; k < pts.length - 1; k++) { const [i0, j0] = pts[k], [i1, j1] = pts[k + 1]; B.quad(B.vertex(X(i0), top(i0, j0), -Y(j0), 0x90a4ae), B.vertex(X(i1), top(i1, j1), -Y(j1), 0x90a4ae), B.vertex(X(i1), h.bottom_mm, -Y(j1), 0x90a4ae), B.vertex(X(i0), h.bottom_mm, -Y(j0), 0x90a4ae)); } };
    const range = (n) => Array.from({ length: n }, (_, k) => k);
    side(range(nx).map((i) => [i, 0])); side(range(nx).map((i) => [i, ny - 1])); side(range(ny).map((j) => [0, j])); side(range(ny).map((j) => [nx - 1, j]));
    B.quad(B.vertex(X(0), h.bottom_mm, -Y(0), 0x78909c), B.vertex(X(nx - 1), h.bottom_mm, -Y(0), 0x78909c), B.vertex(X(nx - 1), h.bottom_mm, -Y(ny - 1), 0x78909c), B.vertex(X(0), h.bottom_mm, -Y(ny - 1), 0x78909c));
    return B.mesh();
  }
  /** A point of the programme in three's coordinates (a lathe's X is a radius, shown at the
   * cut-away's upper face, angle 90 degrees). */
  const glPoint = (p) => (G.data && G.data.head.kind === "lathe" ? [p[2], 0, Math.abs(p[0])] : [p[0], p[2], -p[1]]);
  function glBuild(d, first) {
    glClear();
    G.part = d.head.kind === "lathe" ? latheMesh(d) : millMesh(d);
    G.scene.add(G.part);
    G.marks = new THREE.Group();
    const box = new THREE.Box3().setFromObject(G.part), size = box.getSize(new THREE.Vector3()).length();
    d.head.findings.filter((f) => f.x !== undefined).forEach((f) => {
      const p = glPoint([d.head.kind === "lathe" ? f.x / 2 : f.x, f.y || 0, f.z]);
      // Drawn over the part (no depth test): a finding inside the material is still seen.
      const ball = new THREE.Mesh(new THREE.SphereGeometry(size * 0.015, 16, 12), new THREE.MeshBasicMaterial({ color: 0xd50000, depthTest: false }));
      ball.renderOrder = 10;
      ball.position.set(p[0], p[1], p[2]);
      G.marks.add(ball);
    });
    G.scene.add(G.marks);
    if (first || !G.dist) { const c = box.getCenter(new THREE.Vector3()); G.target = [c.x, c.y, c.z]; G.dist = size * 1.7; }
  }
  /** The tool where the player is: a lathe insert pointing at its tip with a shank behind it; a
   * mill's cutter (its diameter from the setup, else 10 mm) with the holder above. */
  function glTool() {
    if (!S || !S.n || !G.data) { glDropTool(); return; }
    const q = posAt(now), p = glPoint(q), lathe3d = G.data.head.kind === "lathe";
    // In a bore (below the face, inside the stock) the insert points out at the wall and the
    // bar reaches back out past the face; outside, the insert points at the axis, its shank radial.
    const inBore = lathe3d && q[2] < G.data.head.front_z_mm - 1e-6 && Math.abs(q[0]) < G.data.head.diameter_mm / 2 - 1e-6;
    const size = lathe3d ? Math.max(G.data.head.diameter_mm * 0.08, 2) : (+(((JOB.setup || "").match(/diameter_mm\s*=\s*([0-9.]+)/) || [])[1]) || 10) / 2;
    // Made again only when its shape changes; as the player moves it is only moved.
    const key = [lathe3d, inBore, size].join();
    if (!G.tool || G.toolKey !== key) {
      glDropTool();
      G.tool = lathe3d ? latheTool(size, inBore) : millTool(size);
      G.toolKey = key;
      G.scene.add(G.tool);
    }
    G.tool.position.set(p[0], p[1], p[2]);
  }
  function glDropTool() {
    if (!G.tool) return;
    G.scene.remove(G.tool);
    G.tool.traverse((o) => { if (o.geometry) o.geometry.dispose(); if (o.material) o.material.dispose(); });
    G.tool = null;
  }
  const toolSteel = () => new THREE.MeshStandardMaterial({ color: 0xffb300, metalness: 0.4, roughness: 0.4 });
  const toolDark = () => new THREE.MeshStandardMaterial({ color: 0x37474f, metalness: 0.5, roughness: 0.5 });
  /** A lathe insert of size `s` pointing at its tip, with its shank (a boring bar's along the axis). */
  function latheTool(s, inBore) {
    const grp = new THREE.Group();
    const tip = new THREE.Mesh(new THREE.ConeGeometry(s * 0.35, s, 4), toolSteel());
    tip.rotation.x = inBore ? Math.PI / 2 : -Math.PI / 2;
    tip.position.set(0, 0, inBore ? -s / 2 : s / 2);
    const shank = inBore ? new THREE.Mesh(new THREE.BoxGeometry(s * 6, s * 0.5, s * 0.5), toolDark()) : new THREE.Mesh(new THREE.BoxGeometry(s * 0.6, s * 0.6, s * 2.5), toolDark());
    if (inBore) shank.position.set(s * 3, 0, -s * 0.9); else shank.position.set(0, 0, s * 2.2);
    grp.add(tip, shank);
    return grp;
  }
  /** A mill's cutter of radius `r` (the setup's diameter, else 10 mm) with the holder above. */
  function millTool(r) {
    const grp = new THREE.Group();
    const cutter = new THREE.Mesh(new THREE.CylinderGeometry(r, r, 4 * r, 24), toolSteel());
    cutter.position.set(0, 2 * r, 0);
    const holder = new THREE.Mesh(new THREE.CylinderGeometry(r * 2.4, r * 2.4, 5 * r, 24), toolDark());
    holder.position.set(0, 4 * r + 2.5 * r, 0);
    grp.add(cutter, holder);
    return grp;
  }
  function glRender() {
    if (!G.renderer) return;
    const box = $("plot-box"), w = box.clientWidth, h = box.clientHeight;
    G.renderer.setPixelRatio(window.devicePixelRatio || 1);
    G.renderer.setSize(w, h, false);
    G.renderer.domElement.style.width = "100%"; G.renderer.domElement.style.height = "100%";
    G.camera.aspect = w / Math.max(h, 1);
    const [tx, ty, tz] = G.target, dist = G.dist || 100;
    G.camera.position.set(tx + dist * Math.cos(G.pitch) * Math.sin(G.yaw), ty + dist * Math.sin(G.pitch), tz + dist * Math.cos(G.pitch) * Math.cos(G.yaw));
    G.camera.lookAt(tx, ty, tz);
    G.camera.near = dist / 100; G.camera.far = dist * 100;
    G.camera.updateProjectionMatrix();
    glTool();
    G.renderer.render(G.scene, G.camera);
  }

  // ---- start ------------------------------------------------------------------------------------
  applyWords();
  paintEditor(); draw(); showThread(); showPresses(); offerRestore();
  $("pause").disabled = true;
  const ready = compiled.then(() => { if (programmeText().trim()) return run(); banner("ok", t("empty")); }).catch((e) => banner("usage", t("usage", { msg: String(e.message || e) })));
  window.ncsightApp = {
    ready,
    settled,
    get scene() { return S && { head: S.head, n: S.n, h: S.h }; },
    get now() { return now; },
    get runLine() { return runLine; },
    get selLine() { return selLine; },
    get drawMs() { return lastDrawMs; },
    get runMs() { return lastRunMs; },
    get runs() { return runs; },
    get firstPathMs() { return firstPathMs; },
    passes: () => (S ? S.head.passes : 0),
    kindOf: (i) => S.kind[i] & 7,
    startOf: (i) => S.t0[i],
    endOf: (i) => S.t[i],
    holeDepths: () => (S ? Array.from(S.holeAt.filter((_, j) => j % 3 === 2)) : []),
    get machineState() { return machineState; },
    setTime, stepBlock, nextTool, select, zoom, fit: () => { fit(); draw(); }, run, pick,
    stock3d: () => G.data && { head: G.data.head, busy: G.busy || !!G.want, fail: G.fail, note: $("gl-note").textContent },
    view3d: (yaw, pitch, zoom) => { G.yaw = yaw; G.pitch = pitch; if (zoom) G.dist *= zoom; glRender(); },
    part: () => { const st = stock(); return st && Array.from(part(st).r.filter((_, j) => j % 100 === 0)); },
    toScreen: (x, y, z) => { const pv = V(); return [sx(pv.pu[0] * x + pv.pu[1] * y + pv.pu[2] * z), sy(pv.pv[0] * x + pv.pv[1] * y + pv.pv[2] * z)]; },
  };
})();
