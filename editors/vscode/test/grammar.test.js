// Tokenises every scene under the given directory (recursively) with the
// TextMate grammar, through the same engine VS Code uses (vscode-textmate +
// the Oniguruma regex library), and fails if any token is scoped invalid.
// It also checks the scopes of a few known lines, and that the check itself
// notices invalid text.
"use strict";
const fs = require("fs");
const path = require("path");
const vsctm = require("vscode-textmate");
const oniguruma = require("vscode-oniguruma");

const grammarPath = path.join(__dirname, "..", "syntaxes", "hscene.tmLanguage.json");
const wasm = fs.readFileSync(require.resolve("vscode-oniguruma/release/onig.wasm")).buffer;

async function loadGrammar() {
  await oniguruma.loadWASM(wasm);
  const registry = new vsctm.Registry({
    onigLib: Promise.resolve({
      createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
      createOnigString: (s) => new oniguruma.OnigString(s),
    }),
    loadGrammar: async (scopeName) =>
      scopeName === "source.hscene"
        ? vsctm.parseRawGrammar(fs.readFileSync(grammarPath, "utf8"), grammarPath)
        : null,
  });
  return registry.loadGrammar("source.hscene");
}

// [text, scopes] of every token of `text`.
function tokenize(grammar, text) {
  let stack = vsctm.INITIAL;
  const out = [];
  for (const line of text.split(/\r?\n/)) {
    const r = grammar.tokenizeLine(line, stack);
    for (const t of r.tokens) {
      out.push([line.slice(t.startIndex, t.endIndex), t.scopes]);
    }
    stack = r.ruleStack;
  }
  return out;
}

function invalid(tokens) {
  return tokens.filter(([, scopes]) => scopes.some((s) => s.startsWith("invalid")));
}

function scenes(dir) {
  return fs.readdirSync(dir, { withFileTypes: true }).flatMap((e) => {
    const p = path.join(dir, e.name);
    if (e.isDirectory()) return scenes(p);
    return p.endsWith(".hsc") ? [p] : [];
  });
}

function scopeOf(tokens, text) {
  const t = tokens.find(([s]) => s === text);
  if (!t) throw new Error(`no token ${JSON.stringify(text)}`);
  return t[1][t[1].length - 1];
}

function expectEqual(actual, expected, what) {
  if (actual !== expected) {
    throw new Error(`${what}: expected ${expected}, got ${actual}`);
  }
}

async function main() {
  const dir = process.argv[2];
  const grammar = await loadGrammar();
  const files = scenes(dir);
  if (files.length < 20) throw new Error(`only ${files.length} scenes found in ${dir}`);
  let failed = 0;
  for (const file of files) {
    const bad = invalid(tokenize(grammar, fs.readFileSync(file, "utf8")));
    if (bad.length > 0) {
      failed++;
      console.error(`${file}: invalid tokens ${JSON.stringify(bad.map(([t]) => t))}`);
    }
  }

  const sample = tokenize(
    grammar,
    'Objects { ball: Sphere %eye, -0.5e-1, #glass, at = %2; Mesh "m.ply", #1; } // c\n' +
      "Transformations { %2->Rotate(%axis, 0.7); @ball->Reflect(%1); } /* b */"
  );
  expectEqual(scopeOf(sample, "Objects"), "entity.name.section.hscene", "section");
  expectEqual(scopeOf(sample, "ball"), "entity.name.label.hscene", "label");
  expectEqual(scopeOf(sample, "Sphere"), "support.class.object.hscene", "object");
  expectEqual(scopeOf(sample, "%eye"), "variable.other.point.hscene", "point");
  expectEqual(scopeOf(sample, "#glass"), "variable.other.material.hscene", "material");
  expectEqual(scopeOf(sample, "@ball"), "variable.other.object.hscene", "object reference");
  expectEqual(scopeOf(sample, "-0.5e-1"), "constant.numeric.hscene", "number");
  expectEqual(scopeOf(sample, "at"), "variable.parameter.key.hscene", "key");
  expectEqual(scopeOf(sample, '"m.ply"'), "string.quoted.double.hscene", "string");
  expectEqual(scopeOf(sample, "Rotate"), "support.function.transformation.hscene", "move");
  expectEqual(scopeOf(sample, "->"), "keyword.operator.arrow.hscene", "arrow");
  expectEqual(scopeOf(sample, "// c"), "comment.line.double-slash.hscene", "line comment");
  if (invalid(sample).length !== 0) throw new Error("the sample has invalid tokens");
  // The check notices text that is not hscene.
  if (invalid(tokenize(grammar, "Points { (0,0,0) ? }")).length !== 1) {
    throw new Error("a stray `?` is not flagged invalid");
  }

  if (failed > 0) {
    throw new Error(`${failed} of ${files.length} scenes have invalid tokens`);
  }
  console.log(`grammar: ${files.length} scenes tokenised, no invalid tokens; sample scopes ok`);
}

main().catch((e) => {
  console.error(e.message || e);
  process.exit(1);
});
