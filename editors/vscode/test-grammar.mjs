// The TextMate grammar, tokenized as VS Code does it (vscode-textmate with the Oniguruma
// regular expressions of vscode-oniguruma, loaded from node_modules: no network).
// Each case is one line and the scopes that some of its tokens must have.
//   node test-grammar.mjs        (after npm ci; the build runs it)
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';
import { createRequire } from 'node:module';
import vsctm from 'vscode-textmate';
import oniguruma from 'vscode-oniguruma';

const here = dirname(fileURLToPath(import.meta.url));
const require = createRequire(import.meta.url);
const grammarPath = join(here, 'syntaxes', 'gcode-ncsight.tmLanguage.json');
const wasm = readFileSync(join(dirname(require.resolve('vscode-oniguruma')), 'onig.wasm'));

await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
const registry = new vsctm.Registry({
  onigLib: Promise.resolve({
    createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
    createOnigString: (s) => new oniguruma.OnigString(s),
  }),
  loadGrammar: async (scopeName) =>
    scopeName === 'source.gcode.ncsight'
      ? vsctm.parseRawGrammar(readFileSync(grammarPath, 'utf8'), grammarPath)
      : null,
});
const grammar = await registry.loadGrammar('source.gcode.ncsight');
if (!grammar) throw new Error(`no grammar source.gcode.ncsight in ${grammarPath}`);

// [line, [[text in the line, a scope its first character must have], ...]]
const cases = [
  ['N10 G71 U1.5 R0.5 (ROUGH)', [
    ['N10', 'entity.name.label.sequence.ncsight'],
    ['G71', 'keyword.other.gcode.ncsight'],
    ['U', 'variable.parameter.axis.ncsight'],
    ['1.5', 'constant.numeric.ncsight'],
    ['R', 'variable.parameter.axis.ncsight'],
    ['(', 'punctuation.definition.comment.begin.ncsight'],
    ['ROUGH', 'comment.block.ncsight'],
    [')', 'comment.block.ncsight'],
  ]],
  ['#100=[#1+2]*SIN[30]', [
    ['#100', 'variable.other.macro.ncsight'],
    ['=', 'keyword.operator.assignment.ncsight'],
    ['[', 'punctuation.section.brackets.begin.ncsight'],
    ['#1', 'variable.other.macro.ncsight'],
    ['*', 'keyword.operator.arithmetic.ncsight'],
    ['SIN', 'support.function.math.ncsight'],
    ['30', 'constant.numeric.ncsight'],
  ]],
  ['G32.1 X20. Z-30. F2.', [
    ['G32.1', 'keyword.other.gcode.ncsight'],
    ['X', 'variable.parameter.axis.ncsight'],
    ['20.', 'constant.numeric.ncsight'],
    ['-30.', 'constant.numeric.ncsight'],
    ['F', 'support.type.feed.ncsight'],
    ['2.', 'constant.numeric.ncsight'],
  ]],
  ['G12.1', [['G12.1', 'keyword.other.gcode.ncsight']]],
  ['/M01', [
    ['/', 'keyword.control.block-delete.ncsight'],
    ['M01', 'keyword.control.mcode.ncsight'],
  ]],
  ['/2 N20 G0 X10', [
    ['/2', 'keyword.control.block-delete.ncsight'],
    ['N20', 'entity.name.label.sequence.ncsight'],
  ]],
  ['%', [['%', 'keyword.control.tape-mark.ncsight']]],
  ['O0012 (ncsight: gsk980tdi)', [
    ['O0012', 'entity.name.function.programme.ncsight'],
    ['ncsight: gsk980tdi', 'comment.block.ncsight'],
  ]],
  [':0100', [[':0100', 'entity.name.function.programme.ncsight']]],
  ['IF[#1EQ0]GOTO10', [
    ['IF', 'keyword.control.flow.ncsight'],
    ['EQ', 'keyword.operator.word.ncsight'],
    ['GOTO', 'keyword.control.flow.ncsight'],
    ['10', 'entity.name.label.sequence.ncsight'],
  ]],
  ['WHILE[#2LT10]DO1', [
    ['WHILE', 'keyword.control.flow.ncsight'],
    ['LT', 'keyword.operator.word.ncsight'],
    ['DO', 'keyword.control.flow.ncsight'],
  ]],
  ['END1', [['END', 'keyword.control.flow.ncsight']]],
  ['#[#1+100]=ROUND[#5 MOD 3]', [
    ['#', 'variable.other.macro.ncsight'],
    ['ROUND', 'support.function.math.ncsight'],
    ['MOD', 'keyword.operator.word.ncsight'],
  ]],
  ['M98 P1234 L2', [
    ['M98', 'keyword.control.mcode.ncsight'],
    ['P', 'variable.parameter.address.ncsight'],
    ['1234', 'constant.numeric.ncsight'],
    ['L', 'variable.parameter.address.ncsight'],
  ]],
  ['T0101 S800 M03', [
    ['T0101', 'entity.name.type.tool.ncsight'],
    ['S', 'support.type.spindle-speed.ncsight'],
    ['800', 'constant.numeric.ncsight'],
  ]],
  ['G01 X30.,C2. Z-20.,R1.', [
    [',C', 'variable.parameter.drawing.ncsight'],
    [',R', 'variable.parameter.drawing.ncsight'],
  ]],
  ['g1x10z-5f.2', [
    ['g1', 'keyword.other.gcode.ncsight'],
    ['x', 'variable.parameter.axis.ncsight'],
    ['.2', 'constant.numeric.ncsight'],
  ]],
  // ; ends a block on these controllers: what follows is the next block, coloured as such.
  ['G0 X10; G1 Z5', [
    [';', 'punctuation.terminator.end-of-block.ncsight'],
    ['G1', 'keyword.other.gcode.ncsight'],
  ]],
  ['G0 X-4.5.', [['4.5.', 'invalid.illegal.decimal-point.ncsight']]],
  ['G0 X10（FULL）', [['（', 'invalid.illegal.full-width.ncsight']]],
  ['(UNCLOSED COMMENT G0 X1', [['G0 X1', 'comment.block.ncsight']]],
];

let passed = 0;
let failed = 0;
for (const [line, expected] of cases) {
  const { tokens } = grammar.tokenizeLine(line, vsctm.INITIAL);
  const found = tokens.map((t) => ({ start: t.startIndex, text: line.slice(t.startIndex, t.endIndex), scopes: t.scopes }));
  let from = 0;
  for (const [text, scope] of expected) {
    // `text` is looked for from the end of the last one checked; its first character's token
    // must have `scope`.
    const at = line.indexOf(text, from);
    const token = at < 0 ? undefined : found.findLast((t) => t.start <= at);
    if (token && token.scopes.includes(scope)) {
      passed++;
      from = at + text.length;
      continue;
    }
    failed++;
    const got = token ? token.scopes.slice(1).join(' ') || '(no scope)' : 'not in the line';
    console.error(`grammar: in ${JSON.stringify(line)}, ${JSON.stringify(text)} should be ${scope}; it is ${got}`);
    console.error('  tokens: ' + found.map((t) => `${JSON.stringify(t.text)}=${t.scopes.slice(1).join(' ') || '-'}`).join(' '));
  }
}
console.log(`grammar: ${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
