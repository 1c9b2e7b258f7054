//! A fast streaming hasher for content keys: what a drawing is built from,
//! hashed so that equal inputs give equal keys (not for hash tables that
//! face untrusted keys).

use std::hash::Hasher;

/// Builds [`KeyHasher`]s: the hasher of the project's maps and sets whose
/// keys are hashes, indices or numbers of its own (no random seed).
pub type BuildKeyHasher = std::hash::BuildHasherDefault<KeyHasher>;

/// A fast multiplicative hasher with a final avalanche: each step is a
/// bijection, so changing one word always changes the state.
#[derive(Clone, Copy, Debug)]
pub struct KeyHasher(u64);

const K: u64 = 0x517c_c1b7_2722_0a95;

impl Default for KeyHasher {
    fn default() -> KeyHasher {
        KeyHasher(0x2545_f491_4f6c_dd1d)
    }
}

impl Hasher for KeyHasher {
    fn write(&mut self, bytes: &[u8]) {
        let mut chunks = bytes.chunks_exact(8);
        for c in &mut chunks {
            self.write_u64(u64::from_le_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]));
        }
        let rest = chunks.remainder();
        if !rest.is_empty() {
            let mut b = [0u8; 8];
            b[..rest.len()].copy_from_slice(rest);
            // The length keeps "ab" and "ab\0" apart.
            self.write_u64(u64::from_le_bytes(b) ^ ((rest.len() as u64) << 56));
        }
    }

    fn write_u64(&mut self, v: u64) {
        self.0 = (self.0.rotate_left(5) ^ v).wrapping_mul(K);
    }

    fn write_u32(&mut self, v: u32) {
        self.write_u64(u64::from(v));
    }

    fn write_u8(&mut self, v: u8) {
        self.write_u64(u64::from(v));
    }

    fn write_usize(&mut self, v: usize) {
        self.write_u64(v as u64);
    }

    fn finish(&self) -> u64 {
        // The MurmurHash3 finaliser.
        let mut h = self.0;
        h ^= h >> 33;
        h = h.wrapping_mul(0xff51_afd7_ed55_8ccd);
        h ^= h >> 33;
        h = h.wrapping_mul(0xc4ce_b9fe_1a85_ec53);
        h ^ (h >> 33)
    }
}

/// Numbers in [0, 1), the same for the same `seed` (xorshift): for tests that draw many cases.
#[cfg(test)]
pub(crate) fn unit_floats(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    }
}
