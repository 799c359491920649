// The client side of the extension: it starts `hscene lsp` (the server does
// all the work) for every `.hsc` file.
const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");

let client;

function activate(context) {
  const command = vscode.workspace.getConfiguration("hscene").get("path") || "hscene";
  const server = { command, args: ["lsp"] };
  client = new LanguageClient(
    "hscene",
    "hscene language server",
    { run: server, debug: server },
    { documentSelector: [{ scheme: "file", language: "hscene" }, { scheme: "untitled", language: "hscene" }] }
  );
  context.subscriptions.push(client);
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
