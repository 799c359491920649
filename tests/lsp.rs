//! `hscene lsp` driven as an editor drives it: the real binary, JSON-RPC
//! over its stdin and stdout, every read bounded so a broken server fails
//! the test instead of hanging it.

use std::io::{BufRead, BufReader, Read, Write};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::Duration;

use serde_json::{Value, json};

const TIMEOUT: Duration = Duration::from_secs(20);

/// A scene whose first line has characters of 2 and 4 UTF-8 bytes (1 and 2
/// UTF-16 units), so columns after them differ in the two counts.
const SCENE: &str = "\
Points { eye = (0,0,0.5); (0,0,0); q: (0.5,0,0); (0.1, 0.1, 0); } // é𝕏 %q
Globals { from = %eye; to = (0,0,0); fov = 160; }
BRDFs { glass: diffuse = (1,0,0), shininess = 20; }
Objects { ball: Sphere %2, 0.05, #glass; Sphere %4, 0.01, #1; }
Transformations { axis: hline (%2, %q); %2->Translate(%axis); }
";

const URI: &str = "file:///tmp/hscene-lsp-test/scene.hsc";

struct Server {
    child: Child,
    stdin: ChildStdin,
    messages: Receiver<Value>,
    next_id: i64,
}

impl Server {
    fn start() -> Server {
        let mut child = Command::new(env!("CARGO_BIN_EXE_hscene"))
            .arg("lsp")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("start hscene lsp");
        let stdin = child.stdin.take().unwrap();
        let stdout = child.stdout.take().unwrap();
        let (tx, messages) = channel();
        std::thread::spawn(move || {
            let mut reader = BufReader::new(stdout);
            loop {
                let mut length = None;
                loop {
                    let mut line = String::new();
                    if reader.read_line(&mut line).unwrap_or(0) == 0 {
                        return;
                    }
                    let line = line.trim_end();
                    if line.is_empty() {
                        break;
                    }
                    if let Some(n) = line.strip_prefix("Content-Length: ") {
                        length = n.parse::<usize>().ok();
                    }
                }
                let mut body = vec![0; length.expect("Content-Length header")];
                if reader.read_exact(&mut body).is_err() {
                    return;
                }
                let value: Value = serde_json::from_slice(&body).expect("JSON body");
                if tx.send(value).is_err() {
                    return;
                }
            }
        });
        Server {
            child,
            stdin,
            messages,
            next_id: 1,
        }
    }

    fn send(&mut self, message: &Value) {
        let body = message.to_string();
        write!(self.stdin, "Content-Length: {}\r\n\r\n{body}", body.len()).unwrap();
        self.stdin.flush().unwrap();
    }

    fn notify(&mut self, method: &str, params: Value) {
        self.send(&json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }

    /// Sends a request and returns its response's `result` (or `error`).
    fn request(&mut self, method: &str, params: Value) -> Value {
        let id = self.next_id;
        self.next_id += 1;
        self.send(&json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        loop {
            let msg = self.next_message(method);
            if msg["id"] == json!(id) {
                if let Some(err) = msg.get("error") {
                    return json!({ "error": err });
                }
                return msg["result"].clone();
            }
        }
    }

    fn next_message(&self, waiting_for: &str) -> Value {
        self.messages.recv_timeout(TIMEOUT).unwrap_or_else(|_| {
            panic!("no message from the server while waiting for {waiting_for}")
        })
    }

    /// The next `publishDiagnostics` notification.
    fn diagnostics(&self) -> Value {
        loop {
            let msg = self.next_message("publishDiagnostics");
            if msg["method"] == "textDocument/publishDiagnostics" {
                return msg["params"].clone();
            }
        }
    }
}

/// The LSP position (UTF-16 columns) of the `nth` occurrence of `needle`
/// in `text`, plus `delta` characters.
fn pos(text: &str, needle: &str, nth: usize) -> Value {
    let offset = text
        .match_indices(needle)
        .nth(nth)
        .unwrap_or_else(|| panic!("`{needle}` #{nth} not in the text"))
        .0;
    let line_start = text[..offset].rfind('\n').map_or(0, |i| i + 1);
    let line = text[..offset].matches('\n').count();
    let character: usize = text[line_start..offset].chars().map(char::len_utf16).sum();
    json!({"line": line, "character": character})
}

fn at(text: &str, needle: &str, nth: usize) -> Value {
    json!({"textDocument": {"uri": URI}, "position": pos(text, needle, nth)})
}

/// `acosh(1 + 2|p-q|^2 / ((1-|p|^2)(1-|q|^2)))`, the distance in the ball.
fn ball_distance(p: [f64; 3], q: [f64; 3]) -> f64 {
    let n = |v: [f64; 3]| v.iter().map(|x| x * x).sum::<f64>();
    let d = n([p[0] - q[0], p[1] - q[1], p[2] - q[2]]);
    (1.0 + 2.0 * d / ((1.0 - n(p)) * (1.0 - n(q)))).acosh()
}

#[test]
fn a_whole_editor_session() {
    let mut server = Server::start();
    let init = server.request(
        "initialize",
        json!({"processId": null, "rootUri": null, "capabilities": {}}),
    );
    let caps = &init["capabilities"];
    for cap in [
        "hoverProvider",
        "definitionProvider",
        "referencesProvider",
        "renameProvider",
        "completionProvider",
        "documentSymbolProvider",
        "documentFormattingProvider",
    ] {
        assert!(!caps[cap].is_null(), "{cap} not advertised: {caps}");
    }
    server.notify("initialized", json!({}));

    // A broken version first: diagnostics with code and related information.
    let broken = SCENE.replace("Sphere %4, 0.01, #1", "Sphere %4, #glass");
    server.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": URI, "languageId": "hscene", "version": 1, "text": broken}}),
    );
    let published = server.diagnostics();
    assert_eq!(published["uri"], URI);
    let diags = published["diagnostics"].as_array().unwrap();
    let arity = diags
        .iter()
        .find(|d| d["code"] == "HSC0107")
        .unwrap_or_else(|| panic!("no HSC0107 in {diags:?}"));
    assert_eq!(arity["severity"], 1);
    assert_eq!(arity["source"], "hscene");
    assert_eq!(arity["range"]["start"]["line"], 3);
    let related = arity["relatedInformation"]
        .as_array()
        .expect("related information");
    assert!(
        related
            .iter()
            .any(|r| r["location"]["range"]["start"]["line"] == 0),
        "a related location in Points: {related:?}"
    );

    // Fixed by a change: the diagnostics are cleared.
    server.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": URI, "version": 2}, "contentChanges": [{"text": SCENE}]}),
    );
    let published = server.diagnostics();
    assert_eq!(published["version"], 2);
    assert_eq!(published["diagnostics"], json!([]), "{published}");

    // Hover on `%2` in the Sphere: where the translation put it, how far
    // from the eye, with a range in UTF-16 columns.
    let hover = server.request("textDocument/hover", at(SCENE, "%2", 0));
    let text = hover["contents"]["value"].as_str().unwrap();
    assert!(text.contains("point %2"), "{text}");
    assert!(text.contains("Final position"), "{text}");
    let coords: Vec<f64> = text
        .split("after all transformations): `(")
        .nth(1)
        .and_then(|s| s.split(')').next())
        .unwrap()
        .split(", ")
        .map(|x| x.parse().unwrap())
        .collect();
    // Translate along the line from %2 to %q takes %2 onto %q.
    assert!(
        (coords[0] - 0.5).abs() < 1e-12 && coords[1].abs() < 1e-12,
        "{coords:?}"
    );
    let distance: f64 = text
        .split("distance from the eye: `")
        .nth(1)
        .and_then(|s| s.split('`').next())
        .unwrap()
        .parse()
        .unwrap();
    let expected = ball_distance([0.0, 0.0, 0.5], [coords[0], coords[1], coords[2]]);
    assert!(
        (distance - expected).abs() < 1e-9,
        "{distance} vs {expected}"
    );
    assert_eq!(hover["range"]["start"], pos(SCENE, "%2", 0));

    // Hover on a material reference: its fields.
    let hover = server.request("textDocument/hover", at(SCENE, "#glass", 0));
    let text = hover["contents"]["value"].as_str().unwrap();
    assert!(
        text.contains("material #glass") && text.contains("| shininess | `20` |"),
        "{text}"
    );

    // `@camera` is not declared but has a hover: the eye after its moves.
    let with_camera = format!("{SCENE}Transformations {{ @camera->Translate(%axis); }}\n");
    server.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": URI, "version": 3}, "contentChanges": [{"text": with_camera}]}),
    );
    assert_eq!(server.diagnostics()["version"], 3);
    let hover = server.request("textDocument/hover", at(&with_camera, "@camera", 0));
    let text = hover["contents"]["value"].as_str().unwrap();
    assert!(
        text.contains("Eye: `(") && !text.contains("Eye: `(0, 0, 0.5)`"),
        "{text}"
    );
    server.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": URI, "version": 4}, "contentChanges": [{"text": SCENE}]}),
    );
    assert_eq!(server.diagnostics()["version"], 4);

    // Definition of `%q` used in the hline (after non-ASCII text on line 0).
    let def = server.request("textDocument/definition", at(SCENE, "%q", 1));
    assert_eq!(def["uri"], URI);
    assert_eq!(def["range"]["start"], pos(SCENE, "q:", 0));
    // The comment's `%q` on line 0 is not a reference.
    let none = server.request("textDocument/definition", at(SCENE, "%q", 0));
    assert!(none.is_null(), "{none}");

    // References of point 2 (numbered): the Sphere, the hline, the move target.
    let refs = server.request(
        "textDocument/references",
        json!({"textDocument": {"uri": URI}, "position": pos(SCENE, "%2", 1),
               "context": {"includeDeclaration": true}}),
    );
    let starts: Vec<Value> = refs
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["range"]["start"].clone())
        .collect();
    assert_eq!(
        starts,
        vec![
            pos(SCENE, "(0,0,0);", 0),
            pos(SCENE, "%2", 0),
            pos(SCENE, "%2", 1),
            pos(SCENE, "%2", 2),
        ]
    );
    // `%axis` is the line, not a point.
    let refs = server.request(
        "textDocument/references",
        json!({"textDocument": {"uri": URI}, "position": pos(SCENE, "axis:", 0),
               "context": {"includeDeclaration": false}}),
    );
    assert_eq!(refs.as_array().unwrap().len(), 1);

    // Rename `q` (at its declaration): declaration and both `%q`s, the
    // comment left alone.
    let edit = server.request(
        "textDocument/rename",
        json!({"textDocument": {"uri": URI}, "position": pos(SCENE, "q:", 0), "newName": "target"}),
    );
    let edits = edit["changes"][URI].as_array().unwrap();
    assert_eq!(edits.len(), 2, "{edits:?}");
    assert!(edits.iter().all(|e| e["newText"] == "target"));
    // Exact ranges: `q` of the declaration, and the name after the sigil.
    assert_eq!(edits[0]["range"]["start"], pos(SCENE, "q:", 0));
    assert_eq!(edits[1]["range"]["start"], pos(SCENE, "q);", 0));
    assert_eq!(edits[1]["range"]["end"], pos(SCENE, ");", 5));
    // A numbered point has no name to rename; a bad name is refused.
    let refused = server.request(
        "textDocument/rename",
        json!({"textDocument": {"uri": URI}, "position": pos(SCENE, "%2", 0), "newName": "x"}),
    );
    assert!(
        refused["error"]["message"]
            .as_str()
            .unwrap()
            .contains("no name")
    );
    let refused = server.request(
        "textDocument/rename",
        json!({"textDocument": {"uri": URI}, "position": pos(SCENE, "q:", 0), "newName": "2bad"}),
    );
    assert!(!refused["error"].is_null());

    // Completion: names after `#`, object keywords at a statement start.
    let labels = |v: &Value| -> Vec<String> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|i| i["label"].as_str().unwrap().to_owned())
            .collect()
    };
    let items = server.request("textDocument/completion", at(SCENE, "glass;", 0));
    let names = labels(&items);
    assert!(
        names.contains(&"glass".to_owned()) && names.contains(&"1".to_owned()),
        "{names:?}"
    );
    let items = server.request("textDocument/completion", at(SCENE, "ball:", 0));
    assert!(labels(&items).contains(&"Sphere".to_owned()));
    let items = server.request("textDocument/completion", at(SCENE, "Globals", 0));
    assert!(labels(&items).contains(&"Transformations".to_owned()));

    // The outline: sections with what they declare.
    let symbols = server.request(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": URI}}),
    );
    let outline: Vec<(String, Vec<String>)> = symbols
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            let children = s["children"]
                .as_array()
                .unwrap()
                .iter()
                .map(|c| c["name"].as_str().unwrap().to_owned())
                .collect();
            (s["name"].as_str().unwrap().to_owned(), children)
        })
        .collect();
    assert_eq!(
        outline[0],
        (
            "Points".to_owned(),
            vec!["%eye".into(), "%2".into(), "%q".into(), "%4".into()]
        )
    );
    assert_eq!(outline[2], ("BRDFs".to_owned(), vec!["#glass".into()]));
    assert_eq!(outline[4].1, vec!["%axis".to_owned()]);

    // Formatting: one edit giving what `hscene fmt` gives.
    let edits = server.request(
        "textDocument/formatting",
        json!({"textDocument": {"uri": URI}, "options": {"tabSize": 4, "insertSpaces": true}}),
    );
    let edits = edits.as_array().unwrap();
    assert_eq!(edits.len(), 1);
    assert_eq!(edits[0]["newText"], hscene_lang::format(SCENE).unwrap());
    assert_eq!(
        edits[0]["range"]["start"],
        json!({"line": 0, "character": 0})
    );
    assert_eq!(edits[0]["range"]["end"], json!({"line": 5, "character": 0}));

    // An unknown request is an error, not a crash.
    let unknown = server.request(
        "textDocument/codeLens",
        json!({"textDocument": {"uri": URI}}),
    );
    assert_eq!(unknown["error"]["code"], -32601);

    let shutdown = server.request("shutdown", Value::Null);
    assert!(shutdown.is_null());
    server.notify("exit", Value::Null);
    drop(server.stdin);
    // Exits promptly with success after `exit`.
    let started = std::time::Instant::now();
    loop {
        if let Some(status) = server.child.try_wait().unwrap() {
            assert!(status.success(), "{status}");
            break;
        }
        assert!(started.elapsed() < TIMEOUT, "the server did not exit");
        std::thread::sleep(Duration::from_millis(20));
    }
}

#[test]
fn a_client_that_goes_away_ends_the_server() {
    let mut server = Server::start();
    server.request(
        "initialize",
        json!({"processId": null, "rootUri": null, "capabilities": {}}),
    );
    server.notify("initialized", json!({}));
    // A request about a document never opened is an error answer.
    let answer = server.request("textDocument/hover", at(SCENE, "%2", 0));
    assert!(
        answer["error"]["message"]
            .as_str()
            .unwrap()
            .contains("not open")
    );
    // No shutdown, no exit: stdin just closes.
    drop(server.stdin);
    let started = std::time::Instant::now();
    while server.child.try_wait().unwrap().is_none() {
        assert!(
            started.elapsed() < TIMEOUT,
            "the server outlived its client"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

impl Server {
    /// Writes raw bytes, as a broken or hostile client would.
    fn send_raw(&mut self, bytes: &[u8]) {
        self.stdin.write_all(bytes).unwrap();
        self.stdin.flush().unwrap();
    }

    fn initialise(&mut self) {
        self.request(
            "initialize",
            json!({"processId": null, "rootUri": null, "capabilities": {}}),
        );
        self.notify("initialized", json!({}));
    }

    /// Waits for the server to exit; its status.
    fn exit_status(&mut self) -> std::process::ExitStatus {
        let started = std::time::Instant::now();
        loop {
            if let Some(status) = self.child.try_wait().unwrap() {
                return status;
            }
            assert!(started.elapsed() < TIMEOUT, "the server did not exit");
            std::thread::sleep(Duration::from_millis(20));
        }
    }
}

fn framed(body: &[u8]) -> Vec<u8> {
    let mut v = format!("Content-Length: {}\r\n\r\n", body.len()).into_bytes();
    v.extend_from_slice(body);
    v
}

/// Each malformed message gets the JSON-RPC error for it, and the server
/// answers the next request as if nothing happened.
#[test]
fn malformed_messages_are_answered_and_the_server_goes_on() {
    let mut server = Server::start();
    server.initialise();
    let mut deep = "[".repeat(100_000);
    deep.push_str(&"]".repeat(100_000));
    let cases: Vec<(&str, Vec<u8>, i64)> = vec![
        ("not JSON", b"{\"jsonrpc\": \"2.0\", ".to_vec(), -32700),
        (
            "invalid UTF-8",
            b"{\"jsonrpc\":\"2.0\",\"method\":\"\xc3\x28\"}".to_vec(),
            -32700,
        ),
        (
            "a lone surrogate",
            br#"{"jsonrpc":"2.0","id":1,"method":"\udc00"}"#.to_vec(),
            -32700,
        ),
        ("deep nesting", deep.into_bytes(), -32700),
        (
            "a batch",
            br#"[{"jsonrpc":"2.0","id":1,"method":"shutdown"}]"#.to_vec(),
            -32600,
        ),
        ("no method", br#"{"jsonrpc":"2.0","id":5}"#.to_vec(), -32600),
    ];
    for (name, body, code) in cases {
        server.send_raw(&framed(&body));
        let answer = server.next_message(name);
        assert_eq!(answer["error"]["code"], code, "{name}: {answer}");
        assert!(
            answer["id"].is_null() || answer["id"] == 5,
            "{name}: {answer}"
        );
        // Still serving.
        let hover = server.request("textDocument/hover", at(SCENE, "%2", 0));
        assert!(
            hover["error"]["message"]
                .as_str()
                .unwrap()
                .contains("not open"),
            "{name}"
        );
    }
    assert!(server.request("shutdown", Value::Null).is_null());
    server.notify("exit", Value::Null);
    assert!(server.exit_status().success());
}

/// Requests before `initialize` are refused with -32002, and `exit`
/// without `shutdown` ends the server with status 1.
#[test]
fn the_protocol_order_is_kept() {
    let mut server = Server::start();
    let early = server.request("textDocument/hover", at(SCENE, "%2", 0));
    assert_eq!(early["error"]["code"], -32002, "{early}");
    server.initialise();
    server.notify("exit", Value::Null);
    assert_eq!(server.exit_status().code(), Some(1));
}

/// A `Content-Length` of 2^64 - 1 or 2^62 is not allocated: the body is
/// skipped as it arrives, and the stream's end ends the server.
#[test]
fn a_huge_content_length_is_skipped_not_allocated() {
    for length in ["18446744073709551615", "4611686018427387904"] {
        let mut server = Server::start();
        server.initialise();
        server.send_raw(format!("Content-Length: {length}\r\n\r\n{{\"jsonrpc\"").as_bytes());
        drop(server.stdin);
        let status = {
            let started = std::time::Instant::now();
            loop {
                if let Some(status) = server.child.try_wait().unwrap() {
                    break status;
                }
                assert!(started.elapsed() < TIMEOUT, "the server did not exit");
                std::thread::sleep(Duration::from_millis(20));
            }
        };
        assert!(
            status.code().is_some(),
            "{length}: killed by a signal: {status}"
        );
    }
}

/// Endless bytes with no header line end (`hscene lsp < /dev/zero`):
/// the header limit ends the server with status 2 and a reason, in
/// bounded memory.
#[test]
fn endless_garbage_ends_the_server_with_a_reason() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_hscene"))
        .arg("lsp")
        .stdin(std::fs::File::open("/dev/zero").unwrap())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("header line longer than"), "{stderr}");
}

/// An editor that stops reading: the server's writes fail with a broken
/// pipe, and it ends with status 2 and no panic.
#[test]
fn a_client_that_stops_reading_ends_the_server_without_a_panic() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_hscene"))
        .arg("lsp")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    drop(child.stdout.take());
    let init =
        json!({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}});
    let _ = stdin.write_all(&framed(init.to_string().as_bytes()));
    let _ = stdin.flush();
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}

/// Positions of a document with lone-CR line ends, and a document over the
/// scene limit, which is held but not analysed.
#[test]
fn line_ends_and_the_size_limit_are_those_of_check() {
    let mut server = Server::start();
    server.initialise();
    let text = "Points { a = (0,0,0); }\rBRDFs { m: diffuse = (1,1,1); }\rObjects { Sphere %nowhere, 0.1, #m; }\r";
    server.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": URI, "languageId": "hscene", "version": 1, "text": text}}),
    );
    let published = server.diagnostics();
    let undefined = published["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .find(|d| d["code"] == "HSC0201")
        .unwrap_or_else(|| panic!("{published}"))
        .clone();
    let column = "Objects { Sphere ".len();
    assert_eq!(
        undefined["range"]["start"],
        json!({"line": 2, "character": column})
    );
    let big = format!("// {}\n", "x".repeat(16 << 20));
    server.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": URI, "version": 2}, "contentChanges": [{"text": big}]}),
    );
    let published = server.diagnostics();
    let all = published["diagnostics"].as_array().unwrap();
    assert_eq!(all.len(), 1, "{published}");
    assert!(
        all[0]["message"]
            .as_str()
            .unwrap()
            .contains("larger than the limit")
    );
}
