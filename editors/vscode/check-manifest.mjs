// Checks a built .vsix: the files VS Code needs are in it, nothing of the build is, and its
// package.json says what the editor setup (docs/editors.md) promises. Exits 1 with one line per
// problem.
//   node check-manifest.mjs ncsight-0.1.0.vsix
import { readFileSync, readdirSync, existsSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { readVsix } from './vsix.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const root = join(here, '..', '..');
const vsixPath = process.argv[2];
if (!vsixPath) {
  console.error('usage: node check-manifest.mjs FILE.vsix');
  process.exit(2);
}

const problems = [];
const problem = (text) => problems.push(text);
const same = (a, b) => JSON.stringify(a) === JSON.stringify(b);

const zip = readVsix(vsixPath);
const names = new Set(zip.names);

// The files VS Code needs.
const needed = [
  'extension.vsixmanifest',
  'extension/package.json',
  'extension/extension.js',
  'extension/language-configuration.json',
  'extension/syntaxes/gcode-ncsight.tmLanguage.json',
  'extension/readme.md', // vsce writes these two names in lower case
  'extension/changelog.md',
  'extension/node_modules/vscode-languageclient/package.json',
  'extension/node_modules/vscode-languageclient/node.js',
  'extension/node_modules/vscode-languageclient/lib/node/main.js',
  'extension/node_modules/vscode-languageserver-protocol/package.json',
  'extension/node_modules/vscode-jsonrpc/package.json',
];
for (const name of needed) if (!names.has(name)) problem(`${name} is missing from the .vsix`);

// Nothing of the build: the scripts, the devDependencies, type declarations.
for (const name of names) {
  if (/^extension\/(build|check-manifest\.mjs|test-grammar\.mjs|test-extension\.mjs|vsix\.mjs|\.gitignore|\.vscodeignore|package-lock\.json)$/.test(name) ||
      /^extension\/node_modules\/(@vscode\/vsce|vscode-textmate|vscode-oniguruma)\//.test(name) ||
      /\.(d\.ts|map|vsix)$/.test(name)) {
    problem(`${name} should not be in the .vsix`);
  }
}

// The packed manifest.
const text = zip.read('extension/package.json');
const pkg = text ? JSON.parse(text) : {};
const workspace = readFileSync(join(root, 'Cargo.toml'), 'utf8');
const cargoField = (key) => (workspace.match(new RegExp(`^${key}\\s*=\\s*"([^"]*)"`, 'm')) || [])[1];

if (pkg.name !== 'ncsight' || pkg.publisher !== 'ncsight') problem(`name and publisher should be ncsight, not ${pkg.name} and ${pkg.publisher}`);
if (pkg.version !== cargoField('version')) problem(`version ${pkg.version} is not the workspace's ${cargoField('version')} (Cargo.toml)`);
if (pkg.license !== cargoField('license')) problem(`license ${pkg.license} is not the workspace's ${cargoField('license')} (Cargo.toml)`);
if (pkg.main !== './extension.js') problem(`main should be ./extension.js, not ${pkg.main}`);
if (!(pkg.activationEvents || []).includes('onLanguage:gcode-ncsight')) problem('activationEvents lacks onLanguage:gcode-ncsight');

// vscode-languageclient refuses to start on a VS Code older than it needs: engines.vscode must
// not promise less.
const minimum = (range) => (String(range).match(/(\d+)\.(\d+)\.(\d+)/) || []).slice(1).map(Number);
const older = (a, b) => a[0] !== b[0] ? a[0] < b[0] : a[1] !== b[1] ? a[1] < b[1] : a[2] < b[2];
const clientText = zip.read('extension/node_modules/vscode-languageclient/package.json');
if (clientText) {
  const client = JSON.parse(clientText);
  if (!/^9\./.test(client.version)) problem(`vscode-languageclient ${client.version} is packed, not 9.x`);
  const ours = minimum(pkg.engines && pkg.engines.vscode);
  const theirs = minimum(client.engines && client.engines.vscode);
  if (ours.length !== 3 || theirs.length !== 3 || older(ours, theirs)) {
    problem(`engines.vscode ${pkg.engines && pkg.engines.vscode} promises less than vscode-languageclient ${client.version} needs (${client.engines && client.engines.vscode})`);
  }
}

// The language.
const languages = (pkg.contributes && pkg.contributes.languages) || [];
const language = languages.find((l) => l.id === 'gcode-ncsight');
if (!language) {
  problem('contributes.languages has no gcode-ncsight');
} else {
  if (!same(language.aliases, ['G-code (ncsight)', 'ncsight'])) problem(`the aliases are ${JSON.stringify(language.aliases)}`);
  if (!same([...(language.extensions || [])].sort(), ['.NC', '.cnc', '.nc', '.tap'])) problem(`the extensions are ${JSON.stringify(language.extensions)}`);
  if (language.configuration !== './language-configuration.json') problem(`the language configuration is ${language.configuration}`);
  // VS Code anchors firstLine at the start of the line.
  const source = String(language.firstLine || '');
  const firstLine = new RegExp(source.startsWith('^') ? source : '^' + source);
  const programmes = ['%', '  %', 'O0012', 'o1234 (SHAFT)', '(ncsight: fanuc0m)', 'O0001 (PLATE) (ncsight: fanuc0m)', 'G0 X0 (NCSIGHT : gsk988t)'];
  const others = ['Notes for Monday', 'Order 66', 'O', '%!PS-Adobe-3.0', 'ncsight: fanuc0m', '', '; comment'];
  for (const line of programmes) if (!firstLine.test(line)) problem(`firstLine does not take ${JSON.stringify(line)}`);
  for (const line of others) if (firstLine.test(line)) problem(`firstLine takes ${JSON.stringify(line)}, which is no programme`);
}
const grammar = ((pkg.contributes && pkg.contributes.grammars) || []).find((g) => g.language === 'gcode-ncsight');
if (!grammar || grammar.scopeName !== 'source.gcode.ncsight' || grammar.path !== './syntaxes/gcode-ncsight.tmLanguage.json') {
  problem(`contributes.grammars should give gcode-ncsight the scope source.gcode.ncsight in ./syntaxes/gcode-ncsight.tmLanguage.json: ${JSON.stringify(grammar)}`);
} else {
  const packed = zip.read('extension/syntaxes/gcode-ncsight.tmLanguage.json');
  if (packed && JSON.parse(packed).scopeName !== 'source.gcode.ncsight') problem('the grammar file names another scope');
}
const configurationText = zip.read('extension/language-configuration.json');
if (configurationText) {
  const configuration = JSON.parse(configurationText);
  if (!same(configuration.comments && configuration.comments.blockComment, ['(', ')'])) problem('the block comment should be ( )');
  // ; ends a block on these controllers: a line "commented" with it would still run.
  if (configuration.comments && configuration.comments.lineComment) problem(`a line comment ${configuration.comments.lineComment} is set; on these controllers ; ends a block`);
  if (!same(configuration.brackets, [['[', ']'], ['(', ')']])) problem(`the brackets are ${JSON.stringify(configuration.brackets)}`);
}

// The settings.
const properties = (pkg.contributes && pkg.contributes.configuration && pkg.contributes.configuration.properties) || {};
const machine = properties['ncsight.machine'] || {};
const machines = ['gsk980tdi', 'gsk988t', 'fanuc0m', 'fanuc0t', 'yasnac-lx3', 'fanuc0i-tf', 'fanuc0i-mf'];
if (machine.type !== 'string' || !same(machine.enum, machines) || machine.default !== 'gsk980tdi') {
  problem(`ncsight.machine should be a string of ${machines.join(', ')} with the default gsk980tdi: ${JSON.stringify(machine)}`);
}
if (!machine.enumDescriptions || machine.enumDescriptions.length !== machines.length) problem('ncsight.machine needs one description per controller');
const path = properties['ncsight.path'] || {};
if (path.type !== 'string' || path.default !== 'ncsight') problem(`ncsight.path should be a string with the default "ncsight": ${JSON.stringify(path)}`);
const hints = properties['ncsight.inlayHints'] || {};
if (hints.type !== 'boolean' || hints.default !== true) problem(`ncsight.inlayHints should be a boolean with the default true: ${JSON.stringify(hints)}`);

// The controllers of the setting are the profiles the library has (their `name: "..."`).
const profiles = join(root, 'crates', 'ncsight', 'src', 'profile');
if (existsSync(profiles)) {
  const found = new Set();
  for (const file of readdirSync(profiles).filter((f) => f.endsWith('.rs'))) {
    for (const m of readFileSync(join(profiles, file), 'utf8').matchAll(/^\s*name:\s*"([a-z0-9-]+)",/gm)) found.add(m[1]);
  }
  if (found.size === 0) console.log('check-manifest: note: no profile names found in crates/ncsight/src/profile; ncsight.machine not compared with them');
  else if (!same([...found].sort(), [...machines].sort())) problem(`ncsight.machine lists ${machines.join(' ')}; the library's profiles are ${[...found].sort().join(' ')}`);
}

if (problems.length) {
  for (const p of problems) console.error(`check-manifest: ${p}`);
  console.error(`check-manifest: ${vsixPath}: ${problems.length} problem(s)`);
  process.exit(1);
}
console.log(`check-manifest: ${vsixPath}: ${names.size} files, the manifest as promised`);
