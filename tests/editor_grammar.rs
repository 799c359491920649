//! The TextMate grammar in editors/vscode names exactly the sections,
//! objects and transformations the compiler knows (the compiler's own
//! tables), so the highlighting cannot drift from the language. Tokenising
//! every scene with it runs in CI (`.ci/run`, editors/vscode/test).

use std::collections::BTreeSet;

use hscene_lang::vocabulary;

fn grammar() -> serde_json::Value {
    let text = std::fs::read_to_string("editors/vscode/syntaxes/hscene.tmLanguage.json").unwrap();
    serde_json::from_str(&text).unwrap()
}

/// The words of the `\b(a|b|c)\b` rule whose scope is `scope`.
fn alternation(g: &serde_json::Value, scope: &str) -> BTreeSet<String> {
    fn find<'a>(v: &'a serde_json::Value, scope: &str) -> Option<&'a str> {
        match v {
            serde_json::Value::Object(m) => {
                if m.get("name").and_then(|n| n.as_str()) == Some(scope)
                    && let Some(re) = m.get("match").and_then(|r| r.as_str())
                    && re.starts_with("\\b(")
                {
                    return Some(re);
                }
                m.values().find_map(|v| find(v, scope))
            }
            serde_json::Value::Array(a) => a.iter().find_map(|v| find(v, scope)),
            _ => None,
        }
    }
    let re = find(g, scope).unwrap_or_else(|| panic!("no rule {scope}"));
    re.trim_start_matches("\\b(")
        .trim_end_matches(")\\b")
        .split('|')
        .map(str::to_owned)
        .collect()
}

fn set(words: &[&str]) -> BTreeSet<String> {
    words.iter().map(|w| (*w).to_owned()).collect()
}

#[test]
fn grammar_keywords_are_the_compilers() {
    let g = grammar();
    assert_eq!(g["scopeName"], "source.hscene");
    assert_eq!(
        alternation(&g, "entity.name.section.hscene"),
        set(vocabulary::sections())
    );
    assert_eq!(
        alternation(&g, "support.class.object.hscene"),
        set(vocabulary::object_keywords()),
        "objects: {}",
        vocabulary::object_keywords().join("|")
    );
    let mut moves = set(vocabulary::transformations());
    moves.insert("animate".into());
    assert_eq!(
        alternation(&g, "support.function.transformation.hscene"),
        moves
    );
}
