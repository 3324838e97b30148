// Text from outside (commit subjects, author and branch names, a tracer's messages) made safe
// for one kind of output. A commit author controls the bytes of a subject: raw, an ESC or BEL
// rewrites what a developer's terminal or a CI log shows, and in JUnit a control character is
// written as "&#27;", which XML 1.0 forbids, so CI parsers reject the whole report. Each output
// kind calls its function at the one place where its text is written out. Both repair invalid
// UTF-8 first (core/utf8.h); the writers still escape their own markup ('<', '&', '|').
#pragma once

#include <string>
#include <string_view>

namespace raygate {

// For a terminal or a log: C0 controls except tab and newline (so CR and ESC too), DEL, the
// C1 controls (U+0080..U+009F) and the bidirectional overrides and isolates (U+202A..U+202E,
// U+2066..U+2069, which reorder what follows them on screen) become visible escapes: "\x1b",
// "\x7f", "\u009b", "\u202e". Everything else is kept.
std::string terminal_text(std::string_view text);

// terminal_text for one line of output that quotes a document or a tracer: a newline escaped too
// ("\x0a"), so a forged failure text cannot start a line of its own (a fake "gate: PASS" in a CI
// log).
std::string terminal_line(std::string_view text);

// For documents: XML 1.0 (JUnit), HTML and Markdown, before their markup is escaped. What XML
// 1.0 forbids (C0 controls except tab, newline and carriage return; U+FFFE, U+FFFF) and what
// terminal_text hides for being unseen or reordering (DEL, C1, bidi controls) become the same
// visible escapes. Carriage returns are kept: they are line ends in a document.
std::string markup_text(std::string_view text);

}  // namespace raygate
