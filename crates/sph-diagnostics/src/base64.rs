//! Base64 (RFC 4648 §4, standard alphabet, `=` padding) for VTK's inline binary arrays:
//! a streaming encoder, so a large array is never held twice in memory, and a decoder
//! for reading the files back (tests, post-processing). Written here to keep the crate
//! free of dependencies beyond the workspace's.

use std::io::{self, Write};
use thiserror::Error;

const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

/// Encodes bytes written to it into base64 on the inner writer. Call [`finish`] to write
/// the final group with its padding.
///
/// [`finish`]: Base64Writer::finish
pub struct Base64Writer<W: Write> {
    inner: W,
    pending: [u8; 3],
    n_pending: usize,
    out: Vec<u8>,
}

impl<W: Write> Base64Writer<W> {
    /// An encoder writing to `inner`.
    pub fn new(inner: W) -> Self {
        Self {
            inner,
            pending: [0; 3],
            n_pending: 0,
            out: Vec::with_capacity(OUT_CHUNK + 4),
        }
    }

    /// Writes the last partial group (with `=` padding) and returns the inner writer.
    pub fn finish(mut self) -> io::Result<W> {
        if self.n_pending > 0 {
            let group = encode_group(&self.pending[..self.n_pending]);
            self.out.extend_from_slice(&group);
            self.n_pending = 0;
        }
        self.inner.write_all(&self.out)?;
        Ok(self.inner)
    }
}

/// Encoded bytes buffered before they go to the inner writer.
const OUT_CHUNK: usize = 1 << 16;

impl<W: Write> Write for Base64Writer<W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        for &b in buf {
            self.pending[self.n_pending] = b;
            self.n_pending += 1;
            if self.n_pending == 3 {
                let group = encode_group(&self.pending);
                self.out.extend_from_slice(&group);
                self.n_pending = 0;
                if self.out.len() >= OUT_CHUNK {
                    self.inner.write_all(&self.out)?;
                    self.out.clear();
                }
            }
        }
        Ok(buf.len())
    }

    /// Flushes the complete groups (a partial group waits for more bytes or `finish`).
    fn flush(&mut self) -> io::Result<()> {
        self.inner.write_all(&self.out)?;
        self.out.clear();
        self.inner.flush()
    }
}

/// Four characters for one to three bytes, padded with `=`.
fn encode_group(bytes: &[u8]) -> [u8; 4] {
    let b = |i: usize| bytes.get(i).copied().unwrap_or(0) as u32;
    let v = (b(0) << 16) | (b(1) << 8) | b(2);
    let c = |k: u32| ALPHABET[((v >> (18 - 6 * k)) & 63) as usize];
    match bytes.len() {
        1 => [c(0), c(1), b'=', b'='],
        2 => [c(0), c(1), c(2), b'='],
        _ => [c(0), c(1), c(2), c(3)],
    }
}

/// Base64 of `bytes`.
pub fn encode(bytes: &[u8]) -> String {
    let mut w = Base64Writer::new(Vec::with_capacity(bytes.len().div_ceil(3) * 4));
    // Writing to a Vec cannot fail.
    let _ = w.write_all(bytes);
    let out = w.finish().unwrap_or_default();
    // The alphabet and padding are ASCII.
    String::from_utf8(out).unwrap_or_default()
}

/// Why a base64 text could not be decoded.
#[derive(Debug, Error, Clone, PartialEq, Eq)]
pub enum Base64Error {
    /// A character outside the alphabet (whitespace is skipped, not an error).
    #[error("byte {byte:#04x} at position {position} is not base64")]
    InvalidByte {
        /// Position in the text.
        position: usize,
        /// The byte found.
        byte: u8,
    },
    /// The number of characters leaves a single dangling 6-bit group.
    #[error("base64 text has a dangling character (length {0} mod 4 = 1)")]
    BadLength(usize),
}

/// Decodes base64 text, skipping ASCII whitespace (XML may wrap the text) and stopping
/// at the first `=`.
pub fn decode(text: &str) -> Result<Vec<u8>, Base64Error> {
    let mut out = Vec::with_capacity(text.len() / 4 * 3);
    let (mut acc, mut bits, mut count) = (0u32, 0u32, 0usize);
    for (position, &byte) in text.as_bytes().iter().enumerate() {
        if byte.is_ascii_whitespace() {
            continue;
        }
        if byte == b'=' {
            break;
        }
        let v = match byte {
            b'A'..=b'Z' => byte - b'A',
            b'a'..=b'z' => byte - b'a' + 26,
            b'0'..=b'9' => byte - b'0' + 52,
            b'+' => 62,
            b'/' => 63,
            _ => return Err(Base64Error::InvalidByte { position, byte }),
        };
        acc = (acc << 6) | v as u32;
        bits += 6;
        count += 1;
        if bits >= 8 {
            bits -= 8;
            out.push((acc >> bits) as u8);
            acc &= (1 << bits) - 1;
        }
    }
    if count % 4 == 1 {
        return Err(Base64Error::BadLength(count));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn rfc_4648_test_vectors() {
        let cases = [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ];
        for (plain, coded) in cases {
            assert_eq!(encode(plain.as_bytes()), coded);
            assert_eq!(decode(coded).unwrap(), plain.as_bytes());
        }
        assert_eq!(encode(&[0xfb, 0xff]), "+/8=");
        assert_eq!(decode("Zm9v\n  YmFy").unwrap(), b"foobar");
    }

    #[test]
    fn bad_text_is_an_error() {
        assert_eq!(
            decode("Zm9*"),
            Err(Base64Error::InvalidByte {
                position: 3,
                byte: b'*'
            })
        );
        assert_eq!(decode("Zm9vY"), Err(Base64Error::BadLength(5)));
    }

    proptest! {
        #[test]
        fn round_trip(bytes in prop::collection::vec(any::<u8>(), 0..300)) {
            let text = encode(&bytes);
            prop_assert_eq!(text.len(), bytes.len().div_ceil(3) * 4);
            prop_assert_eq!(decode(&text).unwrap(), bytes);
        }

        #[test]
        fn streaming_in_pieces_equals_one_go(
            bytes in prop::collection::vec(any::<u8>(), 0..300),
            cut in 0usize..300,
        ) {
            let cut = cut.min(bytes.len());
            let mut w = Base64Writer::new(Vec::new());
            w.write_all(&bytes[..cut]).unwrap();
            w.flush().unwrap();
            w.write_all(&bytes[cut..]).unwrap();
            let out = w.finish().unwrap();
            prop_assert_eq!(String::from_utf8(out).unwrap(), encode(&bytes));
        }
    }
}
