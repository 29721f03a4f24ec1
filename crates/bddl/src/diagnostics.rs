//! Located messages about a BDDL source: what is wrong, where, and how bad.
//!
//! Every stage (lexer, parser, checker) reports problems as [`Diagnostic`]s that point at a byte
//! range of a [`Source`]. Rendering turns them into `file:line:column` headers with the offending
//! line underlined, so a person can fix a definition without guessing.

use codespan_reporting::diagnostic as cs;
use codespan_reporting::files::SimpleFile;
use codespan_reporting::term;
use std::fmt;
use std::ops::Range;

/// A byte range in a [`Source`]'s text.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Span {
    /// Byte offset of the first byte.
    pub start: u32,
    /// Byte offset one past the last byte; equal to `start` for an empty span (a point).
    pub end: u32,
}

impl Span {
    /// A span from byte offsets. They are stored in 32 bits, which is why sources are limited to
    /// under 4 GiB ([`crate::load::source_from_bytes`] refuses larger ones).
    pub fn new(start: usize, end: usize) -> Self {
        Span {
            start: start as u32,
            end: end as u32,
        }
    }

    /// The smallest span covering both.
    pub fn to(self, other: Span) -> Span {
        Span {
            start: self.start.min(other.start),
            end: self.end.max(other.end),
        }
    }

    /// The span as a range, for slicing the source text: `&source.text[span.range()]`.
    pub fn range(self) -> Range<usize> {
        self.start as usize..self.end as usize
    }
}

/// A named text that diagnostics point into.
#[derive(Clone, Debug)]
pub struct Source {
    /// What rendered diagnostics call it: a file path, or any label for text from elsewhere.
    pub name: String,
    /// The whole text, as read (not lower-cased); spans index it in bytes.
    pub text: String,
}

impl Source {
    /// A source called `name` in diagnostics, holding `text`.
    pub fn new(name: impl Into<String>, text: impl Into<String>) -> Self {
        Source {
            name: name.into(),
            text: text.into(),
        }
    }

    /// One-based line and column (in characters) of a byte offset.
    pub fn line_col(&self, offset: u32) -> (usize, usize) {
        let offset = (offset as usize).min(self.text.len());
        let before = &self.text[..floor_char_boundary(&self.text, offset)];
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let col = before[line_start..].chars().count() + 1;
        (line, col)
    }
}

fn floor_char_boundary(text: &str, mut i: usize) -> usize {
    while !text.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// How bad a diagnostic is; ordered, `Warning < Error`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    /// Suspicious but loadable (e.g. a state on a synset without its ability); comes back with
    /// the result.
    Warning,
    /// The source cannot be used; loading fails with every diagnostic found.
    Error,
}

/// One problem found in a source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    /// Whether it stops the source from loading.
    pub severity: Severity,
    /// One line, without location, e.g. ``unknown predicate `ontopp` ``.
    pub message: String,
    /// The text it is about: underlined when rendered; its start gives the header's `line:col`.
    pub span: Span,
    /// Short text shown under the underline.
    pub label: String,
    /// Extra lines: hints, the reason a rule exists.
    pub notes: Vec<String>,
}

impl Diagnostic {
    /// An error at `span`, without label or notes yet.
    pub fn error(span: Span, message: impl Into<String>) -> Self {
        Diagnostic {
            severity: Severity::Error,
            message: message.into(),
            span,
            label: String::new(),
            notes: Vec::new(),
        }
    }

    /// A warning at `span`, without label or notes yet.
    pub fn warning(span: Span, message: impl Into<String>) -> Self {
        Diagnostic {
            severity: Severity::Warning,
            ..Diagnostic::error(span, message)
        }
    }

    /// Sets the short text shown under the underline.
    pub fn with_label(mut self, label: impl Into<String>) -> Self {
        self.label = label.into();
        self
    }

    /// Adds a note, shown after the excerpt; notes keep the order they are added in.
    pub fn with_note(mut self, note: impl Into<String>) -> Self {
        self.notes.push(note.into());
        self
    }

    /// Whether the severity is [`Severity::Error`].
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }

    /// `file:line:col: error: message` followed by the underlined excerpt and notes.
    pub fn render(&self, source: &Source) -> String {
        let (line, col) = source.line_col(self.span.start);
        let file = SimpleFile::new(&source.name, &source.text);
        let severity = match self.severity {
            Severity::Error => cs::Severity::Error,
            Severity::Warning => cs::Severity::Warning,
        };
        let start = floor_char_boundary(
            &source.text,
            (self.span.start as usize).min(source.text.len()),
        );
        let end = floor_char_boundary(
            &source.text,
            (self.span.end as usize).min(source.text.len()),
        );
        let diagnostic = cs::Diagnostic::new(severity)
            .with_message(&self.message)
            .with_labels(vec![
                cs::Label::primary((), start..end.max(start)).with_message(&self.label),
            ])
            .with_notes(self.notes.clone());
        // Writing into a String cannot fail; on the impossible error the header alone remains.
        let out = term::emit_into_string(&term::Config::default(), &file, &diagnostic)
            .unwrap_or_default();
        // codespan's own first line repeats the message; ours leads with file:line:col instead.
        let excerpt = out.split_once('\n').map_or("", |(_, rest)| rest);
        format!(
            "{}:{line}:{col}: {}\n{excerpt}",
            source.name,
            self.summary()
        )
    }

    fn summary(&self) -> String {
        match self.severity {
            Severity::Error => format!("error: {}", self.message),
            Severity::Warning => format!("warning: {}", self.message),
        }
    }
}

/// The diagnostics of one source, in the order found.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Diagnostics(pub Vec<Diagnostic>);

impl Diagnostics {
    /// Appends a diagnostic.
    pub fn push(&mut self, d: Diagnostic) {
        self.0.push(d);
    }
    /// Whether any diagnostic is an error, i.e. whether the source must be rejected.
    pub fn has_errors(&self) -> bool {
        self.0.iter().any(Diagnostic::is_error)
    }
    /// The errors, in the order found.
    pub fn errors(&self) -> impl Iterator<Item = &Diagnostic> {
        self.0.iter().filter(|d| d.is_error())
    }
    /// The warnings, in the order found.
    pub fn warnings(&self) -> impl Iterator<Item = &Diagnostic> {
        self.0.iter().filter(|d| !d.is_error())
    }
    /// Renders the first [`Diagnostics::SHOWN`] diagnostics and counts the rest: a file that is
    /// wrong everywhere gets a readable report in bounded time.
    pub fn render(&self, source: &Source) -> String {
        let mut out: String = self
            .0
            .iter()
            .take(Self::SHOWN)
            .map(|d| d.render(source))
            .collect();
        if self.0.len() > Self::SHOWN {
            out.push_str(&format!(
                "{}: ... and {} more diagnostic(s)\n",
                source.name,
                self.0.len() - Self::SHOWN
            ));
        }
        out
    }

    /// How many diagnostics [`Diagnostics::render`] shows in full before counting the rest.
    pub const SHOWN: usize = 50;
}

/// A source together with the errors that stopped it from being read; what the loaders return.
#[derive(Clone, Debug)]
pub struct SourceErrors {
    /// The source, kept so that the diagnostics can be rendered with excerpts.
    pub source: Source,
    /// Everything found, warnings included, in the order found; normally at least one error.
    pub diagnostics: Diagnostics,
}

impl fmt::Display for SourceErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.diagnostics.render(&self.source).trim_end())
    }
}

impl std::error::Error for SourceErrors {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn renders_location_excerpt_and_caps_the_count() {
        let source = Source::new("f.bddl", "(a\n  (bad x))");
        let d = Diagnostic::error(Span::new(6, 9), "unknown predicate `bad`").with_label("here");
        let shown = d.render(&source);
        assert!(
            shown.starts_with("f.bddl:2:4: error: unknown predicate `bad`\n"),
            "{shown}"
        );
        assert!(shown.contains("^^^ here"), "{shown}");
        let many = Diagnostics(vec![d; Diagnostics::SHOWN + 10]);
        let shown = many.render(&source);
        assert_eq!(shown.matches("error:").count(), Diagnostics::SHOWN);
        assert!(
            shown.ends_with("f.bddl: ... and 10 more diagnostic(s)\n"),
            "{shown}"
        );
    }
}
