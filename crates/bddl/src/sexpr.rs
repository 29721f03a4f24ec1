//! Lexer and reader: BDDL text to a tree of parenthesised lists of atoms, with spans.
//!
//! BDDL is case-insensitive (the reference lower-cases the whole file), `;` starts a comment that
//! runs to the end of the line, and an atom is any run of characters other than whitespace and
//! parentheses. The reader is iterative and bounds nesting, so no input can exhaust the stack.

use crate::diagnostics::{Diagnostic, Diagnostics, Span};

/// Deeper nesting than this is rejected; real definitions nest fewer than 15 levels.
pub const MAX_DEPTH: usize = 200;

/// An item of the reader's tree.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SExpr {
    /// A word: a name, a keyword such as `:init`, a number or `-`.
    Atom(Atom),
    /// A parenthesised list.
    List(List),
}

/// A lower-cased word, with the span of its original spelling.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Atom {
    /// The word, lower-cased.
    pub text: String,
    /// Where it is written, in its original spelling.
    pub span: Span,
}

/// A parenthesised list; `span` runs from `(` to `)` inclusive.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct List {
    /// The items between the parentheses, in order; possibly none.
    pub items: Vec<SExpr>,
    /// From `(` to `)` inclusive.
    pub span: Span,
}

impl SExpr {
    /// Where the item is written; a list's span includes its parentheses.
    pub fn span(&self) -> Span {
        match self {
            SExpr::Atom(a) => a.span,
            SExpr::List(l) => l.span,
        }
    }

    /// The word, if the item is one.
    pub fn as_atom(&self) -> Option<&Atom> {
        match self {
            SExpr::Atom(a) => Some(a),
            SExpr::List(_) => None,
        }
    }

    /// The list, if the item is one.
    pub fn as_list(&self) -> Option<&List> {
        match self {
            SExpr::List(l) => Some(l),
            SExpr::Atom(_) => None,
        }
    }
}

impl List {
    /// The first item, when it is an atom (the operator or section keyword).
    pub fn head(&self) -> Option<&Atom> {
        self.items.first().and_then(SExpr::as_atom)
    }
}

#[derive(Debug, PartialEq, Eq)]
enum Token {
    Open,
    Close,
    Word,
}

/// Splits text into tokens, skipping whitespace and comments.
fn tokens(text: &str) -> impl Iterator<Item = (Token, Span)> + '_ {
    let bytes = text.as_bytes();
    let mut i = 0;
    std::iter::from_fn(move || {
        loop {
            let b = *bytes.get(i)?;
            match b {
                b';' => {
                    while i < bytes.len() && bytes[i] != b'\n' {
                        i += 1;
                    }
                }
                b'(' | b')' => {
                    i += 1;
                    let token = if b == b'(' { Token::Open } else { Token::Close };
                    return Some((token, Span::new(i - 1, i)));
                }
                _ if b.is_ascii_whitespace() => i += 1,
                _ => {
                    let start = i;
                    while i < bytes.len()
                        && !bytes[i].is_ascii_whitespace()
                        && !matches!(bytes[i], b'(' | b')' | b';')
                    {
                        i += 1;
                    }
                    return Some((Token::Word, Span::new(start, i)));
                }
            }
        }
    })
}

/// Reads exactly one top-level list. Errors carry the span of the offending parenthesis.
pub fn read(text: &str) -> Result<List, Diagnostics> {
    let mut diagnostics = Diagnostics::default();
    // Each open list: its items so far and the span of its `(`.
    let mut stack: Vec<(Vec<SExpr>, Span)> = Vec::new();
    let mut top: Vec<SExpr> = Vec::new();
    for (token, span) in tokens(text) {
        match token {
            Token::Open => {
                if stack.len() >= MAX_DEPTH {
                    diagnostics.push(
                        Diagnostic::error(span, format!("nesting deeper than {MAX_DEPTH} levels"))
                            .with_label("too deep"),
                    );
                    return Err(diagnostics);
                }
                stack.push((Vec::new(), span));
            }
            Token::Close => match stack.pop() {
                Some((items, open)) => {
                    let list = SExpr::List(List {
                        items,
                        span: open.to(span),
                    });
                    match stack.last_mut() {
                        Some((parent, _)) => parent.push(list),
                        None => top.push(list),
                    }
                }
                None => {
                    diagnostics.push(
                        Diagnostic::error(span, "unmatched `)`").with_label("no `(` opens this"),
                    );
                    return Err(diagnostics);
                }
            },
            Token::Word => {
                let atom = SExpr::Atom(Atom {
                    text: text[span.range()].to_lowercase(),
                    span,
                });
                match stack.last_mut() {
                    Some((parent, _)) => parent.push(atom),
                    None => top.push(atom),
                }
            }
        }
    }
    if let Some((_, open)) = stack.last() {
        // The innermost unclosed list is usually where the `)` went missing.
        diagnostics
            .push(Diagnostic::error(*open, "unclosed `(`").with_label("this `(` is never closed"));
        return Err(diagnostics);
    }
    let mut top = top.into_iter();
    let Some(first) = top.next() else {
        diagnostics.push(Diagnostic::error(
            Span::new(0, 0),
            "empty input: expected `(define ...)`",
        ));
        return Err(diagnostics);
    };
    if let Some(extra) = top.next() {
        diagnostics.push(
            Diagnostic::error(extra.span(), "text after the end of the definition")
                .with_label("expected nothing after the closing `)` of `define`"),
        );
    }
    match first {
        SExpr::List(list) if !diagnostics.has_errors() => Ok(list),
        SExpr::List(_) => Err(diagnostics),
        SExpr::Atom(atom) => {
            diagnostics.push(
                Diagnostic::error(atom.span, "expected `(define ...)`").with_label("a bare word"),
            );
            Err(diagnostics)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_nested_lists_lowercased_without_comments() {
        let list = read("(Define ; comment (\n (a ?B) c)").unwrap();
        assert_eq!(list.items.len(), 3);
        assert_eq!(list.head().unwrap().text, "define");
        let inner = list.items[1].as_list().unwrap();
        assert_eq!(inner.items[1].as_atom().unwrap().text, "?b");
        assert_eq!(inner.span, Span::new(21, 27));
    }

    #[test]
    fn reports_unbalanced_parentheses_where_they_are() {
        let err = read("(a (b c)").unwrap_err();
        assert_eq!(err.0[0].message, "unclosed `(`");
        assert_eq!(err.0[0].span, Span::new(0, 1));
        let err = read("(a))").unwrap_err();
        assert_eq!(err.0[0].span, Span::new(3, 4));
        assert!(read("").is_err());
        assert!(read("foo").is_err());
        assert!(read("(a) (b)").is_err());
    }

    #[test]
    fn deep_nesting_is_an_error_not_a_stack_overflow() {
        let text = "(".repeat(100_000);
        let err = read(&text).unwrap_err();
        assert!(err.0[0].message.contains("nesting deeper"));
    }
}
