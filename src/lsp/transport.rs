//! The language server's wire: JSON-RPC messages framed by `Content-Length`
//! headers over a byte stream (the editor's pipe), read with the limits
//! every other input of hscene has.
//!
//! The protocol crate's own reader trusts the header (it allocates whatever
//! length it is told) and ends the server at the first malformed message.
//! This one never allocates more than [`MAX_MESSAGE_BYTES`] for a message,
//! answers a body it cannot use with the JSON-RPC error for it and goes on,
//! and ends only when the framing itself is broken (then no later message
//! can be found) or the stream ends. Writes report a peer that went away as
//! an error instead of panicking.

use std::io::{BufRead, Read, Write};

use lsp_server::{Message, RequestId};
use serde_json::{Value, json};

/// Largest message body read, in bytes (64 MiB): a document at the scene
/// file limit of 16 MiB, JSON-escaped, with room to spare. A larger body is
/// skipped without being held, and answered with an error.
pub const MAX_MESSAGE_BYTES: u64 = 64 << 20;
/// Longest header line, in bytes; headers are short (`Content-Length`,
/// `Content-Type`).
const MAX_HEADER_LINE: u64 = 4096;
/// Most header lines before the blank line that ends them.
const MAX_HEADERS: usize = 16;

/// JSON-RPC's error codes for what arrives broken.
pub const PARSE_ERROR: i32 = -32700;
pub const INVALID_REQUEST: i32 = -32600;

/// What one read produced.
#[derive(Debug)]
pub enum Incoming {
    /// A well-formed request, notification or response.
    Message(Message),
    /// A body that is not a usable message: the error response to send
    /// (with the request's id where one could be read, else null).
    Invalid(Value),
}

/// Why the stream cannot go on.
#[derive(Debug)]
pub enum WireError {
    /// The headers are broken: where the next message starts is unknown.
    Framing(String),
    /// Reading or writing failed (a writer gone: broken pipe).
    Io(std::io::Error),
}

impl std::fmt::Display for WireError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            WireError::Framing(e) => write!(f, "malformed message header: {e}"),
            WireError::Io(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for WireError {}

/// Reads framed messages from `R`, writes them to `W`.
pub struct Transport<R, W> {
    input: R,
    output: W,
}

impl<R: BufRead, W: Write> Transport<R, W> {
    pub fn new(input: R, output: W) -> Self {
        Transport { input, output }
    }

    /// The next message, or `None` when the stream ends (also in the middle
    /// of a message: the peer is gone).
    pub fn read(&mut self) -> Result<Option<Incoming>, WireError> {
        let Some(length) = self.read_headers()? else {
            return Ok(None);
        };
        if length > MAX_MESSAGE_BYTES {
            let skipped = std::io::copy(&mut (&mut self.input).take(length), &mut std::io::sink())
                .map_err(WireError::Io)?;
            if skipped < length {
                return Ok(None);
            }
            return Ok(Some(Incoming::Invalid(error_response(
                None,
                INVALID_REQUEST,
                &format!(
                    "a message of {length} bytes is larger than the limit of {MAX_MESSAGE_BYTES} bytes; it was skipped"
                ),
            ))));
        }
        let mut body = Vec::new();
        (&mut self.input)
            .take(length)
            .read_to_end(&mut body)
            .map_err(WireError::Io)?;
        if (body.len() as u64) < length {
            return Ok(None);
        }
        Ok(Some(decode(&body)))
    }

    /// The body length the headers give, or `None` at the end of the
    /// stream before any header.
    fn read_headers(&mut self) -> Result<Option<u64>, WireError> {
        let mut length = None;
        for index in 0..=MAX_HEADERS {
            let mut line = Vec::new();
            let n = (&mut self.input)
                .take(MAX_HEADER_LINE + 1)
                .read_until(b'\n', &mut line)
                .map_err(WireError::Io)?;
            if n == 0 {
                // The end of the stream: clean between messages, the peer
                // gone within one.
                return Ok(None);
            }
            if line.last() != Some(&b'\n') {
                if n as u64 > MAX_HEADER_LINE {
                    return Err(WireError::Framing(format!(
                        "a header line longer than {MAX_HEADER_LINE} bytes"
                    )));
                }
                return Ok(None);
            }
            let line = line
                .strip_suffix(b"\r\n")
                .or_else(|| line.strip_suffix(b"\n"))
                .unwrap_or(&line);
            if line.is_empty() {
                return match length {
                    Some(length) => Ok(Some(length)),
                    None if index == 0 => Err(WireError::Framing(
                        "a blank line where a header was expected".into(),
                    )),
                    None => Err(WireError::Framing("no Content-Length header".into())),
                };
            }
            let text = std::str::from_utf8(line)
                .map_err(|_| WireError::Framing("a header that is not ASCII".into()))?;
            let (name, value) = text.split_once(':').ok_or_else(|| {
                WireError::Framing(format!("`{}` is not `Name: value`", shorten(text)))
            })?;
            if name.trim().eq_ignore_ascii_case("Content-Length") {
                let value = value.trim();
                let parsed = value
                    .parse::<u64>()
                    .ok()
                    .filter(|_| value.bytes().all(|b| b.is_ascii_digit()));
                length = Some(parsed.ok_or_else(|| {
                    WireError::Framing(format!(
                        "Content-Length `{}` is not a whole number of bytes below 2^64",
                        shorten(value)
                    ))
                })?);
            }
        }
        Err(WireError::Framing(format!(
            "more than {MAX_HEADERS} header lines"
        )))
    }

    /// Sends a message.
    pub fn write(&mut self, message: Message) -> Result<(), WireError> {
        message.write(&mut self.output).map_err(WireError::Io)
    }

    /// Sends a message given as JSON (the error responses whose id is null,
    /// which the protocol crate's types cannot hold).
    pub fn write_value(&mut self, value: &Value) -> Result<(), WireError> {
        let text = value.to_string();
        write!(self.output, "Content-Length: {}\r\n\r\n{text}", text.len())
            .and_then(|()| self.output.flush())
            .map_err(WireError::Io)
    }
}

fn shorten(text: &str) -> String {
    text.chars().take(40).collect()
}

/// A JSON-RPC error response; `id` null when the request's is unknown.
pub fn error_response(id: Option<&RequestId>, code: i32, message: &str) -> Value {
    json!({
        "jsonrpc": "2.0",
        "id": id.map_or(Value::Null, |id| serde_json::to_value(id).unwrap_or(Value::Null)),
        "error": { "code": code, "message": message },
    })
}

/// A body as a message, or the error response JSON-RPC asks for: `-32700`
/// for what is not JSON (or not UTF-8, or nested deeper than the parser's
/// limit of 128), `-32600` for JSON that is not a request, notification or
/// response (a batch, a missing or malformed method or id).
fn decode(body: &[u8]) -> Incoming {
    let invalid = |id: Option<&RequestId>, code, message: String| {
        Incoming::Invalid(error_response(id, code, &message))
    };
    let value: Value = match serde_json::from_slice(body) {
        Ok(v) => v,
        Err(e) => return invalid(None, PARSE_ERROR, format!("the message is not JSON: {e}")),
    };
    let Value::Object(object) = &value else {
        let what = if value.is_array() {
            "a batch (an array); the language server protocol sends one message at a time"
        } else {
            "not a JSON object"
        };
        return invalid(None, INVALID_REQUEST, format!("the message is {what}"));
    };
    let id = match object.get("id") {
        None => None,
        Some(raw) => match serde_json::from_value::<RequestId>(raw.clone()) {
            Ok(id) => Some(id),
            Err(_) => {
                return invalid(
                    None,
                    INVALID_REQUEST,
                    format!(
                        "the id {} is neither a string nor a whole number that fits 32 bits",
                        shorten(&raw.to_string())
                    ),
                );
            }
        },
    };
    match object.get("method") {
        Some(Value::String(_)) => {}
        Some(_) => {
            return invalid(
                id.as_ref(),
                INVALID_REQUEST,
                "the method is not a string".into(),
            );
        }
        None if id.is_some() && (object.contains_key("result") || object.contains_key("error")) => {
        }
        None => {
            return invalid(
                id.as_ref(),
                INVALID_REQUEST,
                "the message has no method".into(),
            );
        }
    }
    // Consumed, not cloned: a document's text is most of a message.
    match serde_json::from_value::<Message>(value) {
        Ok(message) => Incoming::Message(message),
        Err(e) => invalid(
            id.as_ref(),
            INVALID_REQUEST,
            format!("the message is not a JSON-RPC request, notification or response: {e}"),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(body: &[u8]) -> Vec<u8> {
        let mut v = format!("Content-Length: {}\r\n\r\n", body.len()).into_bytes();
        v.extend_from_slice(body);
        v
    }

    fn read_all(input: &[u8]) -> (Vec<Incoming>, Option<WireError>) {
        let mut t = Transport::new(input, Vec::new());
        let mut got = Vec::new();
        loop {
            match t.read() {
                Ok(Some(i)) => got.push(i),
                Ok(None) => return (got, None),
                Err(e) => return (got, Some(e)),
            }
        }
    }

    fn error_code(i: &Incoming) -> i64 {
        match i {
            Incoming::Invalid(v) => v["error"]["code"].as_i64().unwrap(),
            Incoming::Message(m) => panic!("expected an error, got {m:?}"),
        }
    }

    #[test]
    fn malformed_bodies_are_answered_and_the_stream_goes_on() {
        let good = br#"{"jsonrpc":"2.0","id":7,"method":"shutdown"}"#;
        let mut deep = "[".repeat(10_000);
        deep.push_str(&"]".repeat(10_000));
        let cases: Vec<(&str, Vec<u8>, i64)> = vec![
            ("not JSON", b"{not json".to_vec(), -32700),
            ("invalid UTF-8", b"{\"method\":\"\xff\"}".to_vec(), -32700),
            (
                "a lone surrogate",
                br#"{"method":"a\ud800b"}"#.to_vec(),
                -32700,
            ),
            ("deep nesting", deep.into_bytes(), -32700),
            (
                "a batch",
                br#"[{"jsonrpc":"2.0","method":"initialized"}]"#.to_vec(),
                -32600,
            ),
            ("no method", br#"{"jsonrpc":"2.0","id":1}"#.to_vec(), -32600),
            ("a number", b"42".to_vec(), -32600),
            (
                "a method that is a number",
                br#"{"id":1,"method":5}"#.to_vec(),
                -32600,
            ),
            (
                "an id that is an object",
                br#"{"id":{},"method":"x"}"#.to_vec(),
                -32600,
            ),
        ];
        for (name, body, code) in cases {
            let mut input = frame(&body);
            input.extend(frame(good));
            let (got, err) = read_all(&input);
            assert!(err.is_none(), "{name}: {err:?}");
            assert_eq!(got.len(), 2, "{name}");
            assert_eq!(error_code(&got[0]), code, "{name}");
            assert!(
                matches!(&got[1], Incoming::Message(Message::Request(r)) if r.method == "shutdown"),
                "{name}: the next message is read"
            );
        }
        // The error keeps the id when it could be read.
        let (got, _) = read_all(&frame(br#"{"jsonrpc":"2.0","id":3,"method":9}"#));
        match &got[0] {
            Incoming::Invalid(v) => assert_eq!(v["id"], 3),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn a_huge_content_length_allocates_nothing() {
        for length in ["18446744073709551615", "4611686018427387904", "67108865"] {
            let input = format!("Content-Length: {length}\r\n\r\n{{}}");
            let (got, err) = read_all(input.as_bytes());
            // The stream ends inside the skipped body: the peer is gone.
            assert!(got.is_empty() && err.is_none(), "{length}: {got:?} {err:?}");
        }
        // A body over the limit that does arrive is skipped and answered.
        let big = vec![b' '; (MAX_MESSAGE_BYTES + 1) as usize];
        let mut input = frame(&big);
        input.extend(frame(br#"{"jsonrpc":"2.0","method":"exit"}"#));
        let (got, err) = read_all(&input);
        assert!(err.is_none());
        assert_eq!(error_code(&got[0]), -32600);
        assert!(
            matches!(&got[1], Incoming::Message(Message::Notification(n)) if n.method == "exit")
        );
    }

    #[test]
    fn broken_framing_ends_the_stream_with_a_reason() {
        let zeros = vec![0u8; 1 << 20];
        let cases: Vec<(&str, Vec<u8>)> = vec![
            ("endless header", zeros),
            ("no length", b"Content-Type: x\r\n\r\n{}".to_vec()),
            ("not a number", b"Content-Length: -5\r\n\r\n".to_vec()),
            (
                "past 2^64",
                b"Content-Length: 18446744073709551616\r\n\r\n".to_vec(),
            ),
            ("no colon", b"Content-Length 5\r\n\r\n".to_vec()),
            ("many headers", b"X: y\r\n".repeat(100)),
        ];
        for (name, input) in cases {
            let (got, err) = read_all(&input);
            assert!(got.is_empty(), "{name}");
            assert!(
                matches!(err, Some(WireError::Framing(_))),
                "{name}: {err:?}"
            );
        }
    }

    #[test]
    fn a_peer_that_stopped_reading_is_an_error_not_a_panic() {
        struct Gone;
        impl Write for Gone {
            fn write(&mut self, _: &[u8]) -> std::io::Result<usize> {
                Err(std::io::ErrorKind::BrokenPipe.into())
            }
            fn flush(&mut self) -> std::io::Result<()> {
                Err(std::io::ErrorKind::BrokenPipe.into())
            }
        }
        let mut t = Transport::new(&b""[..], Gone);
        let note = lsp_server::Notification::new("x".into(), Value::Null);
        assert!(matches!(
            t.write(Message::Notification(note)),
            Err(WireError::Io(_))
        ));
        assert!(t.write_value(&json!({})).is_err());
    }
}

/// A fuzz target for the wire: framed messages, valid and not, cut,
/// spliced, bit-flipped and given lying headers, fed to [`Transport`].
/// Every stream must end (by its end or a framing error), without a panic,
/// holding no more than the stream (a lying `Content-Length` allocates
/// nothing). Runs for `HSCENE_FUZZ_SECONDS` (CI: 60), else 200 streams.
/// A mutation loop from a fixed seed, not coverage-guided: `cargo fuzz`
/// needs a nightly compiler, and CI has the stable one.
#[cfg(test)]
mod fuzz {
    use hscene_test_support::{FuzzClock, SplitMix64};

    use super::*;

    const BODIES: &[&str] = &[
        r#"{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"capabilities":{}}}"#,
        r#"{"jsonrpc":"2.0","method":"initialized","params":{}}"#,
        r#"{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"file:///a.hsc","languageId":"hscene","version":1,"text":"Points { (0,0,0); }"}}}"#,
        r#"{"jsonrpc":"2.0","id":"x","method":"textDocument/hover","params":{"textDocument":{"uri":"file:///a.hsc"},"position":{"line":0,"character":3}}}"#,
        r#"{"jsonrpc":"2.0","id":2,"result":null}"#,
        r#"[1,2,{"a":[[[[]]]]}]"#,
        "\u{0}\u{1}garbage",
        r#"{"method":"\ud800"}"#,
    ];

    fn stream(rng: &mut SplitMix64) -> Vec<u8> {
        let mut out = Vec::new();
        for _ in 0..1 + rng.below(6) {
            let body = BODIES[rng.below(BODIES.len())].as_bytes();
            let length = match rng.below(8) {
                0 => u64::MAX.to_string(),
                1 => (body.len() + rng.below(10)).to_string(),
                2 => body.len().saturating_sub(rng.below(10)).to_string(),
                3 => format!("{}x", body.len()),
                _ => body.len().to_string(),
            };
            let header = match rng.below(10) {
                0 => format!("content-length:{length}\n\n"),
                1 => format!("Content-Type: x\r\nContent-Length: {length}\r\n\r\n"),
                2 => format!("Content-Length {length}\r\n\r\n"),
                _ => format!("Content-Length: {length}\r\n\r\n"),
            };
            out.extend_from_slice(header.as_bytes());
            out.extend_from_slice(body);
        }
        for _ in 0..rng.below(4) {
            if out.is_empty() {
                break;
            }
            let at = rng.below(out.len());
            match rng.below(4) {
                0 => out[at] ^= 1 << rng.below(8),
                1 => out.truncate(at),
                2 => out.insert(at, rng.below(256) as u8),
                _ => {
                    let end = (at + rng.below(64)).min(out.len());
                    let piece = out[at..end].to_vec();
                    let to = rng.below(out.len());
                    out.splice(to..to, piece);
                }
            }
        }
        out
    }

    #[test]
    fn fuzz_the_transport() {
        let mut clock = FuzzClock::new(200);
        let mut rng = SplitMix64::new(41);
        while clock.next_input() {
            let input = stream(&mut rng);
            let mut t = Transport::new(input.as_slice(), Vec::new());
            // Each read consumes input or ends the stream: the number of
            // reads is bounded by the input's length.
            let mut reads = 0;
            loop {
                reads += 1;
                assert!(reads <= input.len() + 1, "no progress on {input:?}");
                match t.read() {
                    Ok(Some(Incoming::Invalid(v))) => {
                        assert!(v["error"]["code"].is_i64(), "{v}");
                        t.write_value(&v).unwrap();
                    }
                    Ok(Some(Incoming::Message(m))) => t.write(m).unwrap(),
                    Ok(None) | Err(_) => break,
                }
            }
        }
        eprintln!("fuzz_the_transport: {} streams", clock.runs());
    }
}
