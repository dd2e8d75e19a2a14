// The extension as packed, run outside VS Code: the .vsix is unpacked into a temporary folder,
// its extension.js is loaded with the vscode-languageclient it carries, against a stand-in for
// the `vscode` module (only what the extension and the client use) and a stand-in for
// `ncsight lsp` that logs what it receives. No VS Code, no network, no ncsight needed.
//   node test-extension.mjs ncsight-0.1.0.vsix
import { mkdtempSync, mkdirSync, writeFileSync, readFileSync, rmSync, chmodSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { createRequire } from 'node:module';
import { readVsix } from './vsix.mjs';

const vsixPath = process.argv[2];
if (!vsixPath) {
  console.error('usage: node test-extension.mjs FILE.vsix');
  process.exit(2);
}
if (process.platform === 'win32') {
  console.log('extension: the stand-in server is a script with #!: not run on Windows; 0 passed, 0 failed');
  process.exit(0);
}

const work = mkdtempSync(join(tmpdir(), 'ncsight-vsix-'));
const zip = readVsix(vsixPath);
for (const name of zip.names) {
  if (!name.startsWith('extension/')) continue;
  const to = join(work, name);
  mkdirSync(dirname(to), { recursive: true });
  writeFileSync(to, zip.bytesOf(name));
}
const extensionDir = join(work, 'extension');

// The stand-in server: answers initialize, inlay hints and shutdown, publishes one diagnostic
// per opened document, and appends every message it reads to a log, one JSON line each.
const serverLog = join(work, 'server.log');
const server = join(work, 'bin', 'ncsight');
mkdirSync(dirname(server));
writeFileSync(server, `#!${process.execPath}
const fs = require('fs');
const log = (m) => fs.appendFileSync(${JSON.stringify(serverLog)}, JSON.stringify(m) + '\\n');
log({ argv: process.argv.slice(2) });
const send = (m) => {
  const s = JSON.stringify(Object.assign({ jsonrpc: '2.0' }, m));
  process.stdout.write('Content-Length: ' + Buffer.byteLength(s) + '\\r\\n\\r\\n' + s);
};
let buffer = Buffer.alloc(0);
process.stdin.on('data', (data) => {
  buffer = Buffer.concat([buffer, data]);
  for (;;) {
    const head = buffer.indexOf('\\r\\n\\r\\n');
    if (head < 0) return;
    const length = Number(/Content-Length: *(\\d+)/i.exec(buffer.subarray(0, head).toString())[1]);
    if (buffer.length < head + 4 + length) return;
    const message = JSON.parse(buffer.subarray(head + 4, head + 4 + length).toString());
    buffer = buffer.subarray(head + 4 + length);
    log(message);
    if (message.method === 'initialize') {
      send({ id: message.id, result: { capabilities: { textDocumentSync: 1, hoverProvider: true, inlayHintProvider: true } } });
    } else if (message.method === 'textDocument/inlayHint') {
      send({ id: message.id, result: [{ position: { line: 1, character: 6 }, label: '0.4 s' }] });
    } else if (message.method === 'shutdown') {
      send({ id: message.id, result: null });
    } else if (message.method === 'exit') {
      process.exit(0);
    } else if (message.method === 'textDocument/didOpen') {
      send({ method: 'textDocument/publishDiagnostics', params: { uri: message.params.textDocument.uri, diagnostics: [
        { range: { start: { line: 1, character: 0 }, end: { line: 1, character: 2 } }, severity: 1, code: 'NCS-E01', source: 'ncsight', message: 'stand-in alarm' }] } });
    }
  }
});
`);
chmodSync(server, 0o755);
const messages = () => readFileSync(serverLog, 'utf8').trim().split('\n').map((l) => JSON.parse(l));
const clearLog = () => writeFileSync(serverLog, '');
clearLog();

// The stand-in `vscode` module.
const calls = [];
const record = (what, ...args) => calls.push([what, ...args]);
class Disposable {
  constructor(fn) { this.fn = fn; }
  dispose() { if (this.fn) this.fn(); this.fn = undefined; }
  static from(...all) { return new Disposable(() => all.forEach((d) => d && d.dispose && d.dispose())); }
}
const listeners = {};
const event = (name) => (fn, thisArg, disposables) => {
  const list = (listeners[name] ||= []);
  const bound = thisArg ? fn.bind(thisArg) : fn;
  list.push(bound);
  const d = new Disposable(() => list.splice(list.indexOf(bound) >>> 0, 1));
  if (Array.isArray(disposables)) disposables.push(d);
  return d;
};
const fire = (name, ...args) => (listeners[name] || []).slice().forEach((fn) => fn(...args));
class EventEmitter {
  constructor() { this.listeners = []; this.event = (fn, thisArg) => { const b = thisArg ? fn.bind(thisArg) : fn; this.listeners.push(b); return new Disposable(() => { this.listeners = this.listeners.filter((x) => x !== b); }); }; }
  fire(e) { this.listeners.slice().forEach((fn) => fn(e)); }
  dispose() { this.listeners = []; }
}
class Uri {
  constructor(scheme, path) { Object.assign(this, { scheme, path, fsPath: path, authority: '', query: '', fragment: '' }); }
  toString() { return `${this.scheme}://${this.path}`; }
  toJSON() { return this.toString(); }
  with() { return this; }
  static file(path) { return new Uri('file', path); }
  static parse(text) { const m = /^(\w+):\/\/(.*)$/.exec(text); return m ? new Uri(m[1], m[2]) : new Uri('file', text); }
}
class Position { constructor(line, character) { Object.assign(this, { line, character }); } }
class Range { constructor(a, b, c, d) { Object.assign(this, typeof a === 'number' ? { start: new Position(a, b), end: new Position(c, d) } : { start: a, end: b }); } }
class CancellationTokenSource { constructor() { this.token = { isCancellationRequested: false, onCancellationRequested: event('cancel') }; } cancel() {} dispose() {} }
// Whatever else the client touches (enumerations, classes it converts to): an object that
// answers every property, call and construction with another such object.
const anything = (name) => new Proxy(function () {}, {
  get(target, p) {
    if (p === 'then' || p === Symbol.toPrimitive || p === 'toJSON') return undefined;
    if (p === Symbol.iterator) return function* () {};
    if (p === 'prototype') return target.prototype;
    if (p === 'dispose') return () => {};
    if (typeof p === 'string' && /^on[A-Z]/.test(p)) return event(`${name}.${p}`);
    return anything(`${name}.${String(p)}`);
  },
  apply: () => anything(`${name}()`),
  construct: (target, args) => Object.assign(anything(`new ${name}`), { args }),
});

const settings = { machine: 'fanuc0m', path: server, inlayHints: true };
const configuration = (section) => ({
  get: (key, fallback) => {
    const value = section === 'ncsight' ? settings[key] : section === undefined && key === 'ncsight' ? { ...settings } : undefined;
    return value === undefined ? fallback : value;
  },
  has: () => true,
  inspect: () => undefined,
  update: async () => {},
});
const textDocuments = [];
const doc = (path, languageId, text) => {
  const lines = text.split('\n');
  return { uri: Uri.file(path), fileName: path, languageId, version: 1, lineCount: lines.length, isClosed: false, getText: () => text, lineAt: (i) => ({ text: lines[i] }) };
};
const open = (d) => { textDocuments.push(d); fire('open', d); return d; };
const registered = {};
const diagnostics = new Map();
const languages = new Proxy({
  match: (selector, d) => [].concat(selector).some((s) => (typeof s === 'string' ? s === d.languageId
    : (!s.language || s.language === d.languageId) && (!s.scheme || s.scheme === d.uri.scheme))) ? 10 : 0,
  setTextDocumentLanguage: async (d, languageId) => {
    record('setTextDocumentLanguage', d.fileName, languageId);
    const next = { ...d, languageId };
    textDocuments[textDocuments.indexOf(d)] = next;
    fire('close', d);
    fire('open', next);
    return next;
  },
  createDiagnosticCollection: () => ({ set: (uri, list) => diagnostics.set(String(uri), list), delete() {}, clear() {}, dispose() {}, forEach() {}, get: () => undefined, has: () => false }),
}, {
  get: (target, p) => (p in target ? target[p] : (...args) => { registered[p] = args[1]; return new Disposable(); }),
});
const vscode = new Proxy({
  version: '1.90.0',
  Disposable, EventEmitter, Uri, Position, Range, CancellationTokenSource,
  workspace: {
    textDocuments,
    workspaceFolders: undefined,
    getConfiguration: configuration,
    onDidOpenTextDocument: event('open'),
    onDidCloseTextDocument: event('close'),
    onDidChangeConfiguration: event('configuration'),
    onDidChangeTextDocument: event('change'),
    onDidSaveTextDocument: event('save'),
    onWillSaveTextDocument: event('willSave'),
    onDidChangeWorkspaceFolders: event('folders'),
    createFileSystemWatcher: () => anything('watcher'),
  },
  window: {
    showErrorMessage: (...args) => { record('error', ...args); return Promise.resolve(undefined); },
    showWarningMessage: (...args) => { record('warning', ...args); return Promise.resolve(undefined); },
    showInformationMessage: (...args) => { record('information', ...args); return Promise.resolve(undefined); },
    createOutputChannel: () => ({ append() {}, appendLine() {}, show() {}, clear() {}, dispose() {}, replace() {}, hide() {} }),
    visibleTextEditors: [],
    onDidChangeVisibleTextEditors: event('editors'),
    onDidChangeActiveTextEditor: event('activeEditor'),
    tabGroups: { all: [], onDidChangeTabs: event('tabs'), onDidChangeTabGroups: event('tabGroups') },
  },
  languages,
  commands: {
    registerCommand: (id, fn) => { registered[id] = fn; return new Disposable(); },
    executeCommand: async (...args) => record('command', ...args),
  },
  env: { machineId: 'test', sessionId: 'test', language: 'en', appName: 'test', uriScheme: 'vscode' },
}, {
  get: (target, p) => (p in target ? target[p] : typeof p === 'symbol' || p === 'then' || p === '__esModule' ? undefined : anything(`vscode.${p}`)),
});

const require = createRequire(join(extensionDir, 'extension.js'));
const Module = require('module');
const resolve = Module._resolveFilename;
Module._resolveFilename = function (request, ...rest) {
  return request === 'vscode' ? 'vscode' : resolve.call(this, request, ...rest);
};
require.cache.vscode = { id: 'vscode', filename: 'vscode', loaded: true, exports: vscode };
const extension = require(join(extensionDir, 'extension.js'));
const packageJSON = JSON.parse(readFileSync(join(extensionDir, 'package.json'), 'utf8'));

let passed = 0;
let failed = 0;
const check = (ok, what) => {
  if (ok) passed++;
  else { failed++; console.error(`extension: ${what}`); }
};
const until = async (what, test, ms = 10000) => {
  const deadline = Date.now() + ms;
  while (Date.now() < deadline) {
    try { if (test()) return true; } catch { /* not yet */ }
    await new Promise((r) => setTimeout(r, 25));
  }
  console.error(`extension: waited ${ms} ms for ${what}`);
  return false;
};
const sent = (method) => messages().filter((m) => m.method === method);

try {
  // Activation with two .txt files open: only the one that starts like a programme is taken.
  textDocuments.push(doc('/w/notes.txt', 'plaintext', 'Shopping list\nmilk'));
  textDocuments.push(doc('/w/O0012.txt', 'plaintext', 'O0012 (SHAFT)\nG0 X10'));
  const context = { subscriptions: [], extension: { packageJSON } };
  extension.activate(context);
  check(calls.some((c) => c[0] === 'setTextDocumentLanguage' && c[1] === '/w/O0012.txt' && c[2] === 'gcode-ncsight'), 'O0012.txt (first line O0012) was not made a programme');
  check(!calls.some((c) => c[0] === 'setTextDocumentLanguage' && c[1] === '/w/notes.txt'), 'notes.txt was made a programme');

  // The server: `ncsight lsp`, the machine in initializationOptions, the settings, the documents.
  check(await until('didOpen of O0012.txt', () => sent('textDocument/didOpen').length === 1), 'the server did not get the claimed .txt file');
  open(doc('/w/part.nc', 'gcode-ncsight', '(ncsight: fanuc0m)\nG0 X10'));
  check(await until('didOpen of part.nc', () => sent('textDocument/didOpen').length === 2), 'the server did not get part.nc');
  const log = messages();
  check(log[0].argv && log[0].argv.join(' ') === 'lsp', `the server was started with ${JSON.stringify(log[0].argv)}, not lsp`);
  const init = log.find((m) => m.method === 'initialize');
  check(init && JSON.stringify(init.params.initializationOptions) === '{"machine":"fanuc0m"}', `initializationOptions: ${init && JSON.stringify(init.params.initializationOptions)}`);
  const opened = sent('textDocument/didOpen').map((m) => m.params.textDocument);
  check(opened.every((d) => d.languageId === 'gcode-ncsight'), `didOpen language ids: ${opened.map((d) => d.languageId)}`);
  check(opened.some((d) => d.uri === 'file:///w/part.nc' && d.text.startsWith('(ncsight: fanuc0m)')), 'part.nc was not sent with its text');
  check(await until('the configuration', () => sent('workspace/didChangeConfiguration').some((m) => m.params.settings.ncsight && m.params.settings.ncsight.machine === 'fanuc0m')),
    'the ncsight settings were not sent (workspace/didChangeConfiguration)');
  check(await until('diagnostics', () => (diagnostics.get('file:///w/part.nc') || []).length === 1), 'the published diagnostics did not reach VS Code');

  // Inlay hints: asked of the server while ncsight.inlayHints is on, not at all when off.
  const provider = registered.registerInlayHintsProvider;
  check(provider && typeof provider.provideInlayHints === 'function', 'no inlay hint provider was registered');
  if (provider) {
    const part = textDocuments.find((d) => d.fileName === '/w/part.nc');
    const token = new CancellationTokenSource().token;
    const range = new Range(0, 0, 2, 0);
    const before = sent('textDocument/inlayHint').length;
    const on = await provider.provideInlayHints(part, range, token);
    check(sent('textDocument/inlayHint').length === before + 1 && on && on.length === 1, 'with inlayHints on, the server\'s hint did not come back');
    settings.inlayHints = false;
    const off = await provider.provideInlayHints(part, range, token);
    check(sent('textDocument/inlayHint').length === before + 1 && Array.isArray(off) && off.length === 0, 'with inlayHints off, hints were still asked for or shown');
    settings.inlayHints = true;
  }

  // A changed setting restarts the server with it.
  clearLog();
  settings.machine = 'gsk988t';
  fire('configuration', { affectsConfiguration: (s) => s === 'ncsight' || s.startsWith('ncsight.') });
  check(await until('the restart', () => messages().some((m) => m.method === 'initialize')), 'changing ncsight.machine did not restart the server');
  const again = messages().find((m) => m.method === 'initialize');
  check(again && again.params.initializationOptions.machine === 'gsk988t', 'the restarted server did not get the new machine');
  check(await until('the documents again', () => sent('textDocument/didOpen').length === 2), 'the restarted server did not get the open programmes');

  // A missing executable: one error, saying how to install ncsight, and no server.
  settings.path = join(work, 'no-such-dir', 'ncsight');
  fire('configuration', { affectsConfiguration: () => true });
  await until('the missing-program message', () => calls.some((c) => c[0] === 'error'), 3000);
  open(doc('/w/second.nc', 'gcode-ncsight', 'G0 X1'));
  await new Promise((r) => setTimeout(r, 300));
  const errors = calls.filter((c) => c[0] === 'error');
  check(errors.length === 1, `${errors.length} error messages for a missing ncsight, not 1: ${JSON.stringify(errors)}`);
  check(errors.length > 0 && errors[0][1].includes('cargo install --path crates/ncsight-cli') && errors[0][1].includes('release'),
    `the message does not say how to install ncsight: ${errors[0] && errors[0][1]}`);

  // A name on PATH.
  settings.path = 'ncsight';
  process.env.PATH = `${dirname(server)}:${process.env.PATH}`;
  clearLog();
  fire('configuration', { affectsConfiguration: () => true });
  check(await until('the server found on PATH', () => messages().some((m) => m.method === 'initialize')), 'ncsight on PATH was not started');

  await extension.deactivate();
  check(await until('shutdown and exit', () => sent('exit').length === 1), 'deactivate did not stop the server');
} catch (error) {
  failed++;
  console.error('extension:', error);
} finally {
  rmSync(work, { recursive: true, force: true });
}
console.log(`extension: ${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
