//! Fuzz target: arbitrary bytes through `hscene_lang::source::decode`, and
//! (lossily decoded as UTF-8) through
//! `hscene_lang::compile`, then every diagnostic's span through `LineIndex`.
//! Nothing may panic, and every span must lie inside the source on character
//! boundaries.

#![no_main]

use hscene_lang::{LineIndex, compile};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    // Decoding keeps every byte but a BOM and leaves no lone CR.
    if let Ok(text) = hscene_lang::source::decode(data.to_vec()) {
        let bytes = text.as_bytes();
        assert!(data.len() - bytes.len() <= 3);
        assert!(
            (0..bytes.len()).all(|i| bytes[i] != b'\r' || bytes.get(i + 1) == Some(&b'\n'))
        );
    }
    let src = String::from_utf8_lossy(data);
    let compiled = compile(&src);
    let index = LineIndex::new(&src);
    let mut prev = (0, 0);
    for d in &compiled.diagnostics {
        assert!(d.span.start() <= d.span.end() && d.span.end() <= src.len());
        assert!(src.is_char_boundary(d.span.start()) && src.is_char_boundary(d.span.end()));
        assert!(
            (d.span.start(), d.span.end()) >= prev,
            "diagnostics out of order"
        );
        prev = (d.span.start(), d.span.end());
        let start = index.line_col(d.span.start());
        let end = index.line_col(d.span.end());
        assert!(start.0 >= 1 && start.1 >= 1 && end >= start);
        assert!(end.0 <= index.line_count());
        assert_eq!(d.severity, d.code.severity());
        assert!(!d.message.is_empty());
        // Formatting must not panic either.
        let _ = format!("{}:{}: {} {} {d}", start.0, start.1, d.severity, d.code);
    }
    assert_eq!(compiled.scene.is_some(), !compiled.has_errors());
});
