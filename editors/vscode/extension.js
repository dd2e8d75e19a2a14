// ncsight for VS Code: runs `ncsight lsp` on CNC programmes (language id gcode-ncsight).
//
// The server is started when the first programme is opened, not when VS Code starts. A .txt
// file is taken as a programme only when its first line looks like one (see claimTextFile).
// Changing any ncsight.* setting restarts the server, so a new path, controller or inlay-hint
// choice applies at once; the settings are also sent to the server (workspace/didChangeConfiguration).
'use strict';

const fs = require('fs');
const path = require('path');
const vscode = require('vscode');
const { LanguageClient } = require('vscode-languageclient/node');

const LANGUAGE = 'gcode-ncsight';
const SECTION = 'ncsight';

/** @type {LanguageClient | undefined} */
let client;
/** @type {Promise<void> | undefined} */
let starting;
/** The .txt files already looked at (claimed or not): a file switched back to Plain Text stays so. */
const lookedAt = new Set();
/** The ncsight.path value whose absence was last reported: said once, not at every file opened. */
let reportedMissing;

function activate(context) {
  const firstLine = firstLineRegExp(context.extension.packageJSON);
  const onOpen = (document) => {
    claimTextFile(document, firstLine);
    if (document.languageId === LANGUAGE) void start(context);
  };
  context.subscriptions.push(
    vscode.workspace.onDidOpenTextDocument(onOpen),
    vscode.workspace.onDidChangeConfiguration((event) => {
      if (!event.affectsConfiguration(SECTION)) return;
      reportedMissing = undefined;
      void restart(context);
    }),
    vscode.commands.registerCommand('ncsight.restart', () => {
      reportedMissing = undefined;
      return restart(context);
    }),
  );
  vscode.workspace.textDocuments.forEach(onOpen);
}

function deactivate() {
  return stop();
}

// VS Code gives every .txt file to Plain Text before it looks at `firstLine` (a path match wins
// over a first-line match), so the first-line rule of package.json is applied here to .txt
// files on disk: a first line starting with % or O and digits, or holding (ncsight: ...).
function claimTextFile(document, firstLine) {
  const uri = document.uri;
  if (document.languageId !== 'plaintext' || uri.scheme !== 'file') return;
  if (!uri.fsPath.toLowerCase().endsWith('.txt') || lookedAt.has(uri.toString())) return;
  lookedAt.add(uri.toString());
  if (document.lineCount > 0 && firstLine && firstLine.test(document.lineAt(0).text)) {
    void vscode.languages.setTextDocumentLanguage(document, LANGUAGE);
  }
}

function firstLineRegExp(packageJSON) {
  const language = packageJSON.contributes.languages.find((l) => l.id === LANGUAGE);
  if (!language || !language.firstLine) return undefined;
  // As VS Code reads it: anchored at the start of the line.
  const source = language.firstLine.startsWith('^') ? language.firstLine : '^' + language.firstLine;
  return new RegExp(source);
}

function start(context) {
  if (client) return Promise.resolve();
  if (!starting) {
    starting = startClient(context).finally(() => {
      starting = undefined;
    });
  }
  return starting;
}

async function startClient(context) {
  const settings = vscode.workspace.getConfiguration(SECTION);
  const wanted = settings.get('path') || 'ncsight';
  const command = findExecutable(wanted);
  if (!command) {
    if (reportedMissing !== wanted) notFound(wanted);
    reportedMissing = wanted;
    return;
  }
  const next = new LanguageClient(
    SECTION,
    'ncsight',
    { command, args: ['lsp'] },
    {
      documentSelector: [
        { scheme: 'file', language: LANGUAGE },
        { scheme: 'untitled', language: LANGUAGE },
      ],
      initializationOptions: { machine: settings.get('machine') || 'gsk980tdi' },
      synchronize: { configurationSection: SECTION },
      middleware: {
        provideInlayHints: (document, range, token, nextHints) =>
          vscode.workspace.getConfiguration(SECTION, document.uri).get('inlayHints', true)
            ? nextHints(document, range, token)
            : [],
      },
    },
  );
  try {
    await next.start();
    client = next;
  } catch (error) {
    if (error && error.code === 'ENOENT') notFound(wanted);
    else void vscode.window.showErrorMessage(`ncsight: the language server did not start (${command} lsp): ${error && error.message ? error.message : error}`);
    try {
      await next.dispose();
    } catch {
      // the server never ran: nothing to stop
    }
  }
}

async function stop() {
  if (starting) await starting;
  const running = client;
  client = undefined;
  if (!running) return;
  try {
    await running.stop();
  } catch {
    // the server had already ended
  }
}

async function restart(context) {
  await stop();
  if (vscode.workspace.textDocuments.some((d) => d.languageId === LANGUAGE)) await start(context);
}

// `wanted` as the operating system would run it: an absolute path, a path relative to the first
// workspace folder, or a name looked up on PATH (with PATHEXT on Windows).
function findExecutable(wanted) {
  const windows = process.platform === 'win32';
  const suffixes = windows
    ? [''].concat((process.env.PATHEXT || '.EXE;.CMD;.BAT;.COM').split(';').filter(Boolean))
    : [''];
  const runnable = (file) => {
    for (const suffix of suffixes) {
      const candidate = file + suffix;
      try {
        if (!fs.statSync(candidate).isFile()) continue;
        if (!windows) fs.accessSync(candidate, fs.constants.X_OK);
        return candidate;
      } catch {
        // not there, or not executable: try the next
      }
    }
    return undefined;
  };
  if (wanted.startsWith('~/') || wanted.startsWith('~\\')) {
    wanted = path.join(require('os').homedir(), wanted.slice(2));
  }
  if (path.isAbsolute(wanted)) return runnable(wanted);
  if (wanted.includes('/') || wanted.includes('\\')) {
    const folder = vscode.workspace.workspaceFolders && vscode.workspace.workspaceFolders[0];
    return folder ? runnable(path.join(folder.uri.fsPath, wanted)) : undefined;
  }
  for (const dir of (process.env.PATH || '').split(path.delimiter)) {
    if (!dir) continue;
    const found = runnable(path.join(dir, wanted));
    if (found) return found;
  }
  return undefined;
}

function notFound(wanted) {
  const message =
    `ncsight: "${wanted}" was not found, so programmes are coloured but not checked. ` +
    'Install ncsight from its source with `cargo install --path crates/ncsight-cli`, or take the ' +
    'binary for your system from an ncsight release and put it on PATH; or set ncsight.path to the ' +
    'executable.';
  void vscode.window.showErrorMessage(message, 'Open the setting').then((choice) => {
    if (choice) void vscode.commands.executeCommand('workbench.action.openSettings', 'ncsight.path');
  });
}

module.exports = { activate, deactivate };
