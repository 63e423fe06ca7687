// The MASL extension's client: starts `masl lsp` (the language server of masl-lsp) for .masl files and
// restarts it when its settings change. Colours come from the TextMate grammar, without the server.
'use strict';

const vscode = require('vscode');
const { LanguageClient } = require('vscode-languageclient/node');

let client;

function serverOptions() {
  const settings = vscode.workspace.getConfiguration('masl');
  const args = ['lsp'];
  const agentPath = settings.get('agentPath', '');
  if (agentPath) {
    args.push('--agent-path', agentPath);
  }
  const folder = vscode.workspace.workspaceFolders && vscode.workspace.workspaceFolders[0];
  return {
    command: settings.get('server.command', 'masl'),
    args,
    // Relative agent path entries are read from the workspace folder.
    options: folder ? { cwd: folder.uri.fsPath } : {},
  };
}

async function start() {
  client = new LanguageClient('masl', 'MASL', serverOptions(), {
    documentSelector: [{ scheme: 'file', language: 'masl' }, { scheme: 'untitled', language: 'masl' }],
    // A descriptor edited on disk changes what the programs mean: the server checks them again.
    synchronize: { fileEvents: vscode.workspace.createFileSystemWatcher('**/*.xml') },
  });
  try {
    await client.start();
  } catch (error) {
    vscode.window.showErrorMessage(
      `MASL: cannot start "${serverOptions().command} lsp" (${error.message}). ` +
      'Set masl.server.command to the masl command, e.g. masl-cli/build/install/masl/bin/masl.');
  }
}

async function restart() {
  if (client) {
    await client.stop().catch(() => undefined);
  }
  await start();
}

function activate(context) {
  context.subscriptions.push(vscode.commands.registerCommand('masl.restartServer', restart));
  context.subscriptions.push(vscode.workspace.onDidChangeConfiguration((event) => {
    if (event.affectsConfiguration('masl')) {
      restart();
    }
  }));
  return start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
