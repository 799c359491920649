//! The fenced blocks of a Markdown text (CommonMark's backtick fences, as
//! the docs write them: the fence may be indented inside a list item).

/// One fenced block: its info string, the line of its opening fence
/// (1-based) and its lines, the fence's indentation removed.
pub struct Block {
    pub info: String,
    pub line: usize,
    pub lines: Vec<String>,
}

/// The fenced blocks of `md`, in order.
pub fn blocks(md: &str) -> Vec<Block> {
    let mut out = Vec::new();
    let mut open: Option<(usize, Block)> = None;
    for (k, line) in md.lines().enumerate() {
        let trimmed = line.trim_start();
        let indent = line.len() - trimmed.len();
        match open.take() {
            None => {
                if let Some(info) = trimmed.strip_prefix("```") {
                    let block = Block {
                        info: info.trim().to_owned(),
                        line: k + 1,
                        lines: Vec::new(),
                    };
                    open = Some((indent, block));
                }
            }
            Some((fence_indent, mut block)) => {
                if trimmed.starts_with("```") {
                    out.push(block);
                } else {
                    let cut = line
                        .char_indices()
                        .take_while(|&(i, c)| i < fence_indent && c == ' ')
                        .count();
                    block.lines.push(line[cut..].to_owned());
                    open = Some((fence_indent, block));
                }
            }
        }
    }
    out
}

#[test]
fn fences_are_found_with_their_info_and_indentation() {
    let md = "text\n```sh\nhscene man\n```\n- item\n  ```hsc\n  Globals {}\n  ```\n";
    let b = blocks(md);
    assert_eq!(b.len(), 2);
    assert_eq!((b[0].info.as_str(), b[0].line), ("sh", 2));
    assert_eq!(b[0].lines, ["hscene man"]);
    assert_eq!(b[1].info, "hsc");
    assert_eq!(b[1].lines, ["Globals {}"]);
}
