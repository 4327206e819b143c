//! Streaming input shared by the readers: bytes pulled from any reader (a file, a gzip
//! decoder, a slice) through one buffer, handed out as lines, tokens across lines, or
//! fixed-size binary records.
//!
//! Guarantees: the buffer holds the unconsumed part of the current line or record plus at
//! most one chunk read ahead, so reading needs memory for the longest line, not for the
//! input: a gzip file that expands to gigabytes of blank lines or comments is read in a
//! few hundred kilobytes. A line longer than [`MAX_LINE`] bytes is refused
//! ([`ReadErrorKind::LineTooLong`]) rather than buffered. Lines are split at `\n` (a `\r`
//! before it is dropped), numbered from 1; byte offsets count from the start of the
//! (decompressed) input.
//!
//! Why not `BufRead::read_until` into a `Vec` per line: it copies every line once more
//! and does not bound the line's length (a line without `\n` is read whole).

use std::io::Read;

use super::error::{Location, ReadError, ReadErrorKind as K};
use super::text::is_space;

/// Bytes requested from the reader at a time.
pub(crate) const CHUNK: usize = 256 << 10;

/// Records reserved ahead when the input's length is unknown (compressed or piped input):
/// enough that a large mesh's vectors double only a few times as it is read, few enough
/// that a small input declaring a huge count reserves at most a megabyte or two (with a
/// million, every such input reserved tens of megabytes).
pub(crate) const UNKNOWN_LEN_RESERVE: u64 = 1 << 16;

/// The longest line (terminator excluded) a text reader accepts: far above any real
/// record (a 64 MiB face line would list millions of corners), low enough that a
/// decompression bomb made of one endless line is refused in bounded memory.
pub const MAX_LINE: usize = 64 << 20;

/// The error kind for an error met while reading through a gzip decoder: `Decompress`
/// for what the decoder reports about the data (corrupt, or cut short), `Io` for the
/// underlying stream's own failures, which the decoder passes on unchanged.
pub(crate) fn gzip_error(e: std::io::Error) -> K {
    use std::io::ErrorKind as E;
    match e.kind() {
        E::InvalidInput | E::InvalidData | E::UnexpectedEof => K::Decompress(e.to_string()),
        _ => K::Io(e),
    }
}

/// A byte stream read through one reusable buffer; see the module docs.
pub(crate) struct Input<'r> {
    reader: Box<dyn Read + 'r>,
    /// Whether `reader` decompresses gzip (its errors are then classified by
    /// [`gzip_error`]).
    gzip: bool,
    /// `buf[pos..]` is read but not consumed.
    buf: Vec<u8>,
    pos: usize,
    /// Offset in the input of `buf[0]`.
    base: u64,
    eof: bool,
    /// Lines handed out so far.
    line: usize,
    /// The input's total length, when known before reading (an uncompressed file or slice).
    known_len: Option<u64>,
    /// The current line of [`Input::next_token`]: `buf[tok_pos..tok_end]` is what remains of it.
    tok_pos: usize,
    tok_end: usize,
    /// The line number of the last token handed out (0 before any).
    tok_line: usize,
}

impl<'r> Input<'r> {
    /// Reads `reader`, whose length is `known_len` when the caller knows it (gzip content
    /// must already be wrapped in a decoder, `gzip` then true).
    pub(crate) fn new(reader: Box<dyn Read + 'r>, gzip: bool, known_len: Option<u64>) -> Self {
        Input {
            reader,
            gzip,
            buf: Vec::new(),
            pos: 0,
            base: 0,
            eof: false,
            line: 0,
            known_len,
            tok_pos: 0,
            tok_end: 0,
            tok_line: 0,
        }
    }

    /// Reads in-memory bytes (their length known).
    pub(crate) fn from_slice(bytes: &'r [u8]) -> Self {
        Self::new(Box::new(bytes), false, Some(bytes.len() as u64))
    }

    /// Number of the last line handed out (0 before the first).
    pub(crate) fn line(&self) -> usize {
        self.line
    }

    /// Offset in the input of the next byte not consumed.
    pub(crate) fn offset(&self) -> u64 {
        self.base + self.pos as u64
    }

    /// Bytes not yet consumed, when the input's length is known.
    pub(crate) fn remaining(&self) -> Option<u64> {
        self.known_len.map(|n| n.saturating_sub(self.offset()))
    }

    /// Whether the bytes are decompressed from gzip.
    pub(crate) fn is_gzip(&self) -> bool {
        self.gzip
    }

    /// Records the input's total length, learnt another way (a first pass).
    pub(crate) fn set_known_len(&mut self, len: Option<u64>) {
        self.known_len = len;
    }

    /// The input's total length when known before reading.
    pub(crate) fn known_len(&self) -> Option<u64> {
        self.known_len
    }

    /// How many of `declared` records to reserve room for, each at least `min_bytes` long:
    /// never more than the rest of the input could hold when its length is known, never
    /// more than [`UNKNOWN_LEN_RESERVE`] records when it is not (the vector then grows
    /// as records arrive), so that no header count alone drives an allocation.
    pub(crate) fn reserve_for(&self, declared: u64, min_bytes: u64) -> usize {
        let bound = match self.remaining() {
            Some(r) => (r + 1) / min_bytes.max(1),
            None => UNKNOWN_LEN_RESERVE,
        };
        usize::try_from(declared.min(bound)).unwrap_or(usize::MAX)
    }

    /// Whether the whole input has been consumed.
    pub(crate) fn at_end(&mut self) -> Result<bool, ReadError> {
        if self.pos < self.buf.len() {
            return Ok(false);
        }
        self.fill()?;
        Ok(self.pos >= self.buf.len())
    }

    /// Reads one more chunk after the unconsumed bytes (moved to the front of the buffer);
    /// `false` at the end of the input.
    fn fill(&mut self) -> Result<bool, ReadError> {
        if self.eof {
            return Ok(false);
        }
        if self.pos > 0 {
            // Keep the current token line's bounds valid across the move.
            let shift = self.pos;
            self.buf.drain(..shift);
            self.base += shift as u64;
            self.pos = 0;
            self.tok_pos = self.tok_pos.saturating_sub(shift);
            self.tok_end = self.tok_end.saturating_sub(shift);
        }
        let before = self.buf.len();
        // Grow by half at most (not the doubling `read_to_end` would do), so that a line
        // near the limit does not leave twice its size reserved.
        if self.buf.capacity() - before < CHUNK {
            self.buf.reserve_exact(CHUNK.max(before / 2));
        }
        let gzip = self.gzip;
        let offset = self.base + before as u64;
        (&mut self.reader)
            .take(CHUNK as u64)
            .read_to_end(&mut self.buf)
            .map_err(|e| {
                let kind = if gzip { gzip_error(e) } else { K::Io(e) };
                ReadError::new(kind, Location::ByteOffset(offset))
            })?;
        if self.buf.len() == before {
            self.eof = true;
            return Ok(false);
        }
        Ok(true)
    }

    /// Up to `n` unconsumed bytes (fewer only at the end of the input), without consuming.
    pub(crate) fn peek(&mut self, n: usize) -> Result<&[u8], ReadError> {
        while self.buf.len() - self.pos < n && self.fill()? {}
        let end = self.buf.len().min(self.pos + n);
        Ok(&self.buf[self.pos..end])
    }

    /// At least `n` unconsumed bytes when the input has them (else what remains), and
    /// whatever more the buffer already holds: a batch of records to decode in place
    /// before [`Input::consume`].
    pub(crate) fn fill_at_least(&mut self, n: usize) -> Result<&[u8], ReadError> {
        while self.buf.len() - self.pos < n && self.fill()? {}
        Ok(&self.buf[self.pos..])
    }

    /// Marks `n` bytes (at most those last returned) as consumed.
    pub(crate) fn consume(&mut self, n: usize) {
        self.pos = (self.pos + n).min(self.buf.len());
    }

    /// Consumes everything left and returns how many bytes that was.
    pub(crate) fn drain(&mut self) -> Result<u64, ReadError> {
        let start = self.offset();
        loop {
            self.pos = self.buf.len();
            if !self.fill()? {
                return Ok(self.offset() - start);
            }
        }
    }

    /// The next line: its number and its bounds in the buffer (without the terminator).
    fn next_line_span(&mut self) -> Result<Option<(usize, usize, usize)>, ReadError> {
        let mut scanned = 0;
        let end = loop {
            let from = self.pos + scanned;
            if let Some(i) = memchr::memchr(b'\n', &self.buf[from..]) {
                let end = from + i;
                break end;
            }
            scanned = self.buf.len() - self.pos;
            if scanned > MAX_LINE {
                return Err(ReadError::at_line(
                    K::LineTooLong { limit: MAX_LINE },
                    self.line + 1,
                ));
            }
            if !self.fill()? {
                if self.pos >= self.buf.len() {
                    return Ok(None);
                }
                break self.buf.len();
            }
        };
        if end - self.pos > MAX_LINE {
            return Err(ReadError::at_line(
                K::LineTooLong { limit: MAX_LINE },
                self.line + 1,
            ));
        }
        let start = self.pos;
        self.pos = (end + 1).min(self.buf.len());
        self.line += 1;
        let end = if end > start && self.buf[end - 1] == b'\r' {
            end - 1
        } else {
            end
        };
        Ok(Some((self.line, start, end)))
    }

    /// The next line without its terminator (`\n`, `\r\n`), and its 1-based number.
    pub(crate) fn next_line(&mut self) -> Result<Option<(usize, &[u8])>, ReadError> {
        Ok(self
            .next_line_span()?
            .map(|(n, start, end)| (n, &self.buf[start..end])))
    }

    /// The next line that has a token once a `comment` character and what follows it
    /// are removed; returns the line with the comment removed.
    pub(crate) fn next_data_line(
        &mut self,
        comment: u8,
    ) -> Result<Option<(usize, &[u8])>, ReadError> {
        while let Some((n, start, end)) = self.next_line_span()? {
            let line = &self.buf[start..end];
            let cut = memchr::memchr(comment, line).unwrap_or(line.len());
            if line[..cut].iter().any(|&b| !is_space(b)) {
                return Ok(Some((n, &self.buf[start..start + cut])));
            }
        }
        Ok(None)
    }

    /// The next whitespace-separated token, read across lines, with its line.
    pub(crate) fn next_token(&mut self) -> Result<Option<(usize, &[u8])>, ReadError> {
        Ok(self
            .next_token_span()?
            .map(|(n, start, end)| (n, &self.buf[start..end])))
    }

    /// [`Input::next_token`] as its line and its bounds, to pass to [`Input::bytes`].
    pub(crate) fn next_token_span(&mut self) -> Result<Option<(usize, usize, usize)>, ReadError> {
        loop {
            let rest = &self.buf[self.tok_pos..self.tok_end];
            if let Some(skip) = rest.iter().position(|&b| !is_space(b)) {
                let start = self.tok_pos + skip;
                let len = self.buf[start..self.tok_end]
                    .iter()
                    .position(|&b| is_space(b))
                    .unwrap_or(self.tok_end - start);
                self.tok_pos = start + len;
                return Ok(Some((self.tok_line, start, start + len)));
            }
            match self.next_line_span()? {
                Some((n, start, end)) => {
                    self.tok_line = n;
                    self.tok_pos = start;
                    self.tok_end = end;
                }
                None => {
                    self.tok_pos = 0;
                    self.tok_end = 0;
                    return Ok(None);
                }
            }
        }
    }

    /// The buffered bytes `start..end`, bounds given by [`Input::next_token_span`] since
    /// the last call that reads.
    pub(crate) fn bytes(&self, start: usize, end: usize) -> &[u8] {
        self.buf.get(start..end).unwrap_or_default()
    }

    /// Drops what remains of the current token line.
    pub(crate) fn skip_token_line(&mut self) {
        self.tok_pos = self.tok_end;
    }

    /// The line of the last token handed out (0 before any).
    pub(crate) fn token_line(&self) -> usize {
        self.tok_line
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A reader that hands out at most `step` bytes per call, to cross every buffer edge.
    struct Trickle<'a> {
        bytes: &'a [u8],
        step: usize,
    }

    impl Read for Trickle<'_> {
        fn read(&mut self, out: &mut [u8]) -> std::io::Result<usize> {
            let n = self.step.min(out.len()).min(self.bytes.len());
            out[..n].copy_from_slice(&self.bytes[..n]);
            self.bytes = &self.bytes[n..];
            Ok(n)
        }
    }

    /// A reader that returns its scripted results one per call (an empty chunk is the end
    /// of one `fill`'s read), then fails: a read the code should not make shows as an
    /// error.
    struct Script(std::collections::VecDeque<&'static [u8]>);

    impl Read for Script {
        fn read(&mut self, out: &mut [u8]) -> std::io::Result<usize> {
            let Some(chunk) = self.0.pop_front() else {
                return Err(std::io::Error::other("read past the script"));
            };
            assert!(chunk.len() <= out.len());
            out[..chunk.len()].copy_from_slice(chunk);
            Ok(chunk.len())
        }
    }

    fn scripted(chunks: &[&'static [u8]]) -> Input<'static> {
        Input::new(
            Box::new(Script(chunks.iter().copied().collect())),
            false,
            None,
        )
    }

    fn lines_of(input: &mut Input<'_>) -> Vec<(usize, Vec<u8>)> {
        let mut out = Vec::new();
        while let Some((n, l)) = input.next_line().unwrap() {
            out.push((n, l.to_vec()));
        }
        out
    }

    #[test]
    fn lines_are_split_at_newlines_and_numbered_whatever_the_read_sizes() {
        let text = b"a b\r\n\n # c\n  d # e\nf";
        let expected: Vec<(usize, Vec<u8>)> = vec![
            (1, b"a b".to_vec()),
            (2, b"".to_vec()),
            (3, b" # c".to_vec()),
            (4, b"  d # e".to_vec()),
            (5, b"f".to_vec()),
        ];
        assert_eq!(lines_of(&mut Input::from_slice(text)), expected);
        for step in 1..4 {
            let r = Trickle { bytes: text, step };
            assert_eq!(
                lines_of(&mut Input::new(Box::new(r), false, None)),
                expected
            );
        }
        let mut data = Input::from_slice(text);
        assert_eq!(data.next_data_line(b'#').unwrap(), Some((1, &b"a b"[..])));
        assert_eq!(data.next_data_line(b'#').unwrap(), Some((4, &b"  d "[..])));
        assert_eq!(data.next_data_line(b'#').unwrap(), Some((5, &b"f"[..])));
        assert_eq!(data.next_data_line(b'#').unwrap(), None);
    }

    #[test]
    fn long_lines_cross_chunks_and_too_long_lines_are_refused_where_they_start() {
        let mut text = b"first\n".to_vec();
        text.extend(std::iter::repeat_n(b'x', CHUNK * 3 + 5));
        text.extend(b"\nlast");
        let r = Trickle {
            bytes: &text,
            step: 1000,
        };
        let lines = lines_of(&mut Input::new(Box::new(r), false, None));
        assert_eq!(lines.len(), 3);
        assert_eq!(lines[1].1.len(), CHUNK * 3 + 5);
        assert_eq!(lines[2], (3, b"last".to_vec()));

        let endless = std::io::repeat(b' ').take(MAX_LINE as u64 + CHUNK as u64 * 2);
        let mut input = Input::new(Box::new(b"ok\n".chain(endless)), false, None);
        assert_eq!(input.next_line().unwrap(), Some((1, &b"ok"[..])));
        let e = input.next_line().unwrap_err();
        assert!(matches!(e.kind, K::LineTooLong { limit: MAX_LINE }), "{e}");
        assert_eq!(e.location, Location::Line(2));
        assert!(input.buf.capacity() < MAX_LINE * 3 / 2 + 4 * CHUNK);
    }

    #[test]
    fn tokens_run_across_lines_and_records_across_reads() {
        let text = b"solid x\n  facet\tnormal 0 0 1\n\nendsolid";
        let r = Trickle {
            bytes: text,
            step: 3,
        };
        let mut input = Input::new(Box::new(r), false, None);
        let mut got = Vec::new();
        while let Some((n, t)) = input.next_token().unwrap() {
            got.push((n, String::from_utf8(t.to_vec()).unwrap()));
            if t == b"solid" {
                input.skip_token_line();
            }
        }
        let want: Vec<(usize, String)> = [
            (1, "solid"),
            (2, "facet"),
            (2, "normal"),
            (2, "0"),
            (2, "0"),
            (2, "1"),
            (4, "endsolid"),
        ]
        .iter()
        .map(|&(n, s)| (n, s.to_string()))
        .collect();
        assert_eq!(got, want);

        let bytes: Vec<u8> = (0..=255).collect();
        let r = Trickle {
            bytes: &bytes,
            step: 7,
        };
        let mut input = Input::new(Box::new(r), false, None);
        assert_eq!(input.peek(4).unwrap(), &[0, 1, 2, 3]);
        let mut seen = Vec::new();
        loop {
            let at = input.offset();
            let batch = input.fill_at_least(50).unwrap();
            if batch.len() < 50 {
                assert_eq!(at, 250);
                assert_eq!(batch, &bytes[250..]);
                break;
            }
            let whole = batch.len() / 50 * 50;
            seen.extend_from_slice(&batch[..whole]);
            input.consume(whole);
        }
        assert_eq!(seen, &bytes[..250]);
        assert_eq!(input.drain().unwrap(), 6);
        assert!(input.at_end().unwrap());
    }

    #[test]
    fn reservations_are_bounded_by_the_rest_of_a_known_input_or_a_fixed_count() {
        let text = [b'x'; 107];
        let mut input = Input::from_slice(&text);
        assert_eq!(
            (input.known_len(), input.remaining()),
            (Some(107), Some(107))
        );
        // One byte more than the rest: a last record may lack its terminator.
        assert_eq!(input.reserve_for(1000, 12), 9);
        assert_eq!(input.reserve_for(5, 12), 5);
        assert_eq!(input.reserve_for(1000, 0), 108);
        assert_eq!(input.peek(10).unwrap().len(), 10);
        input.consume(10);
        assert_eq!(input.remaining(), Some(97));
        assert_eq!(input.reserve_for(1000, 12), 8);
        input.set_known_len(Some(50));
        assert_eq!((input.known_len(), input.remaining()), (Some(50), Some(40)));
        input.set_known_len(Some(4));
        assert_eq!(input.remaining(), Some(0));
        input.set_known_len(None);
        assert_eq!(input.remaining(), None);
        assert_eq!(input.reserve_for(u64::MAX, 12), 1 << 16);
        assert_eq!(input.reserve_for(70_000, 0), 1 << 16);
        assert_eq!(input.reserve_for(3, 12), 3);
    }

    #[test]
    fn reads_happen_only_when_the_buffer_lacks_what_is_asked() {
        // `at_end` with unconsumed bytes, and `peek` / `fill_at_least` of exactly what is
        // buffered, do not read; an error of the stream is located at its byte offset.
        let mut input = scripted(&[b"abc", b""]);
        assert_eq!(input.peek(2).unwrap(), b"ab");
        assert_eq!(input.peek(3).unwrap(), b"abc");
        assert!(!input.at_end().unwrap());
        assert!(!input.at_end().unwrap());
        assert_eq!(input.fill_at_least(3).unwrap(), b"abc");
        input.consume(1);
        let e = input.peek(5).unwrap_err();
        assert!(matches!(e.kind, K::Io(_)), "{e}");
        assert_eq!(e.location, Location::ByteOffset(3));

        let mut input = scripted(&[b"abc", b"", b"def", b""]);
        assert_eq!(input.fill_at_least(2).unwrap(), b"abc");
        input.consume(2);
        assert_eq!(input.peek(2).unwrap(), b"cd");
        assert_eq!(input.offset(), 2);
        input.consume(2);
        assert_eq!(input.fill_at_least(2).unwrap(), b"ef");
        assert!(input.peek(3).is_err());
    }

    #[test]
    fn the_buffer_holds_the_current_line_and_one_chunk_and_grows_by_half() {
        // Short lines: consumed bytes are dropped at every read.
        let text: Vec<u8> = b"123456789\n".repeat(CHUNK * 8 / 10 + 3);
        let mut input = Input::from_slice(&text);
        let mut count = 0;
        while let Some((n, line)) = input.next_line().unwrap() {
            assert_eq!(line, b"123456789");
            count = n;
            assert!(input.buf.len() <= CHUNK + 10, "{}", input.buf.len());
            assert!(input.buf.capacity() < 2 * CHUNK);
        }
        assert_eq!(count, CHUNK * 8 / 10 + 3);

        // One long line read a chunk at a time: when less than a chunk is free, room for
        // a chunk or half the buffer more, whichever is larger.
        let long = vec![b'x'; 20 * CHUNK];
        let mut input = Input::from_slice(&long);
        let mut model = 0usize;
        for k in 1..=20 {
            let len = (k - 1) * CHUNK;
            if model - len < CHUNK {
                model = len + CHUNK.max(len / 2);
            }
            assert_eq!(input.fill_at_least(len + 1).unwrap().len(), k * CHUNK);
            assert_eq!(input.buf.capacity(), model, "read {k}");
        }
        assert!(model < 20 * CHUNK * 3 / 2);
    }

    #[test]
    fn a_line_of_the_limit_is_read_and_one_byte_longer_is_refused() {
        let mut text = vec![b'x'; MAX_LINE];
        text.extend(b"\nshort\n");
        let mut input = Input::from_slice(&text);
        assert_eq!(
            input.next_line().unwrap().map(|(n, l)| (n, l.len())),
            Some((1, MAX_LINE))
        );
        assert_eq!(input.next_line().unwrap(), Some((2, &b"short"[..])));
        assert_eq!(input.next_line().unwrap(), None);

        // The terminator arrives in the read that crosses the limit: refused after it.
        let mut text = b"ok\n".to_vec();
        text.extend(std::iter::repeat_n(b'x', MAX_LINE + 1));
        text.extend(b"\n");
        let mut input = Input::from_slice(&text);
        assert_eq!(input.next_line().unwrap(), Some((1, &b"ok"[..])));
        let e = input.next_line().unwrap_err();
        assert!(matches!(e.kind, K::LineTooLong { limit: MAX_LINE }), "{e}");
        assert_eq!(e.location, Location::Line(2));
    }
}
