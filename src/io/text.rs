//! Allocation-free line and token scanning over in-memory bytes, shared by the text readers.

/// Iterates over the lines of a byte buffer, tracking 1-based line numbers.
pub(crate) struct Lines<'a> {
    bytes: &'a [u8],
    pos: usize,
    line: usize,
}

impl<'a> Lines<'a> {
    /// Starts at the beginning of `bytes`, before line 1.
    pub(crate) fn new(bytes: &'a [u8]) -> Self {
        Lines {
            bytes,
            pos: 0,
            line: 0,
        }
    }

    /// Bytes not yet consumed.
    pub(crate) fn remaining(&self) -> usize {
        self.bytes.len() - self.pos
    }

    /// The next line without its terminator (`\n`, `\r\n`), and its 1-based number.
    pub(crate) fn next_line(&mut self) -> Option<(usize, &'a [u8])> {
        let rest = self.bytes.get(self.pos..)?;
        if rest.is_empty() {
            return None;
        }
        let (mut line, advance) = match rest.iter().position(|&b| b == b'\n') {
            Some(i) => (&rest[..i], i + 1),
            None => (rest, rest.len()),
        };
        if let [head @ .., b'\r'] = line {
            line = head;
        }
        self.pos += advance;
        self.line += 1;
        Some((self.line, line))
    }

    /// The next line that has a token once a `comment` character and what follows it
    /// are removed; returns the line with the comment removed.
    pub(crate) fn next_data_line(&mut self, comment: u8) -> Option<(usize, &'a [u8])> {
        while let Some((n, line)) = self.next_line() {
            let line = match line.iter().position(|&b| b == comment) {
                Some(i) => &line[..i],
                None => line,
            };
            if line.iter().any(|b| !is_space(*b)) {
                return Some((n, line));
            }
        }
        None
    }
}

/// ASCII whitespace within a line (space, tab, CR, vertical tab, form feed).
#[inline]
pub(crate) fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | 0x0b | 0x0c)
}

/// Iterates over whitespace-separated tokens of one line.
#[derive(Clone)]
pub(crate) struct Tokens<'a> {
    s: &'a [u8],
    pos: usize,
}

impl<'a> Tokens<'a> {
    /// Tokens of `s`.
    pub(crate) fn new(s: &'a [u8]) -> Self {
        Tokens { s, pos: 0 }
    }
}

impl<'a> Iterator for Tokens<'a> {
    type Item = &'a [u8];

    #[inline]
    fn next(&mut self) -> Option<&'a [u8]> {
        let s = self.s;
        let mut i = self.pos;
        while i < s.len() && is_space(s[i]) {
            i += 1;
        }
        if i >= s.len() {
            self.pos = i;
            return None;
        }
        let start = i;
        while i < s.len() && !is_space(s[i]) {
            i += 1;
        }
        self.pos = i;
        Some(&s[start..i])
    }
}

/// A finite `f64` from a token, or `None` (not a number, NaN or infinite).
#[inline]
pub(crate) fn parse_f64(tok: &[u8]) -> Option<f64> {
    parse_any_f64(tok).filter(|x| x.is_finite())
}

/// An `f64` from a token in the syntax of `f64::from_str` (NaN and infinities included),
/// correctly rounded, or `None`.
///
/// Why `fast-float2` rather than `str::parse`: the same syntax and the same (correctly
/// rounded) results, without a UTF-8 check first, at 2.1 times the speed on the 6.3
/// million coordinate tokens of B0's OFF text (134 against 64 million per second, medians
/// of one run of `cargo bench --bench io -- floats`); the tests below hold it to the
/// standard library's results.
#[inline]
pub(crate) fn parse_any_f64(tok: &[u8]) -> Option<f64> {
    fast_float2::parse::<f64, _>(tok).ok()
}

/// A decimal unsigned integer (optional leading `+`), or `None` (including on overflow).
#[inline]
pub(crate) fn parse_u64(tok: &[u8]) -> Option<u64> {
    let digits = match tok {
        [b'+', rest @ ..] => rest,
        _ => tok,
    };
    if digits.is_empty() {
        return None;
    }
    let mut v: u64 = 0;
    for &b in digits {
        let d = b.wrapping_sub(b'0');
        if d > 9 {
            return None;
        }
        v = v.checked_mul(10)?.checked_add(u64::from(d))?;
    }
    Some(v)
}

/// A decimal signed integer (optional sign), or `None` (including on overflow).
#[inline]
pub(crate) fn parse_i64(tok: &[u8]) -> Option<i64> {
    match tok {
        [b'-', rest @ ..] => {
            let v = parse_u64(rest)?;
            if rest.first() == Some(&b'+') {
                return None;
            }
            0i64.checked_sub_unsigned(v)
        }
        _ => i64::try_from(parse_u64(tok)?).ok(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_and_tokens() {
        let mut l = Lines::new(b"a b\r\n\n # c\n  d # e\nf");
        assert_eq!(l.next_data_line(b'#'), Some((1, &b"a b"[..])));
        assert_eq!(l.next_data_line(b'#'), Some((4, &b"  d "[..])));
        assert_eq!(l.next_data_line(b'#'), Some((5, &b"f"[..])));
        assert_eq!(l.next_data_line(b'#'), None);
        let t: Vec<&[u8]> = Tokens::new(b" 1\t2  3 ").collect();
        assert_eq!(t, vec![&b"1"[..], b"2", b"3"]);
    }

    #[test]
    fn numbers() {
        assert_eq!(parse_u64(b"18446744073709551615"), Some(u64::MAX));
        assert_eq!(parse_u64(b"18446744073709551616"), None);
        assert_eq!(parse_u64(b"+7"), Some(7));
        assert_eq!(parse_u64(b"-7"), None);
        assert_eq!(parse_u64(b""), None);
        assert_eq!(parse_i64(b"-9223372036854775808"), Some(i64::MIN));
        assert_eq!(parse_i64(b"-9223372036854775809"), None);
        assert_eq!(parse_i64(b"-+1"), None);
        assert_eq!(parse_i64(b"-3"), Some(-3));
        assert_eq!(parse_f64(b"nan"), None);
        assert_eq!(parse_f64(b"inf"), None);
        assert_eq!(parse_f64(b"1e400"), None);
        assert_eq!(parse_f64(b"-0.5e1"), Some(-5.0));
        assert_eq!(parse_f64(b"\xff"), None);
    }

    /// The standard library's parse, the reference for [`parse_any_f64`].
    fn std_f64(tok: &[u8]) -> Option<f64> {
        std::str::from_utf8(tok).ok()?.parse().ok()
    }

    fn same(a: Option<f64>, b: Option<f64>) -> bool {
        match (a, b) {
            (Some(x), Some(y)) => x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()),
            (None, None) => true,
            _ => false,
        }
    }

    #[test]
    fn agrees_with_the_standard_parser_on_edge_cases() {
        for tok in [
            &b"0"[..],
            b"-0",
            b"+0",
            b"1.",
            b".5",
            b".",
            b"-.",
            b"e5",
            b"1e",
            b"1e+",
            b"1e-5",
            b"1E5",
            b"inf",
            b"-inf",
            b"+inf",
            b"Infinity",
            b"INF",
            b"infin",
            b"nan",
            b"NaN",
            b"-nan",
            b"+nan",
            b"0x10",
            b"1_000",
            b" 1",
            b"1 ",
            b"",
            b"+",
            b"-",
            b"++1",
            b"1..2",
            b"4.9e-324",
            b"2.4e-324",
            b"1.7976931348623157e308",
            b"1.8e308",
            b"1e400",
            b"0.30000000000000004",
            b"9007199254740993",
            b"00000000000000000000001.5",
            b"1.00000000000000011102230246251565404236316680908203125",
            b"\xff",
        ] {
            assert!(
                same(parse_any_f64(tok), std_f64(tok)),
                "{:?}",
                String::from_utf8_lossy(tok)
            );
        }
    }

    proptest::proptest! {
        /// Tokens over the characters of decimal syntax, and printed doubles.
        #[test]
        fn agrees_with_the_standard_parser(
            tok in "[-+]?[0-9]{0,20}(\\.[0-9]{0,20})?([eE][-+]?[0-9]{0,4})?|[-+.0-9eEinfatyINFATY]{0,12}",
            x in proptest::num::f64::ANY,
        ) {
            proptest::prop_assert!(same(parse_any_f64(tok.as_bytes()), std_f64(tok.as_bytes())), "{:?}", tok);
            let printed = format!("{x:e}");
            proptest::prop_assert!(same(parse_any_f64(printed.as_bytes()), Some(x)), "{}", printed);
            let printed = x.to_string();
            proptest::prop_assert!(same(parse_any_f64(printed.as_bytes()), Some(x)), "{}", printed);
        }
    }
}
