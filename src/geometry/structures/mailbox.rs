//! Mailboxing (Amanatides & Woo, 1987; Arnaldi, Priol & Bouatouch, 1987): a
//! structure that lists a primitive in several cells or leaves must still hand
//! it to a ray once, or the ray would test it again in every cell it crosses.
//! The grid, the octree and the BSP tree share this one set of the primitives
//! a walk has handed out.

use arrayvec::ArrayVec;

/// The primitives one walk has visited. It lives for one call, so a structure
/// stays shareable between threads and a `visit` may walk another structure
/// (or this one) without confusing the marks: the first [`Mailbox::FEW`] in an
/// inline list checked in place (most rays of a Whitted scene meet a handful,
/// and the list costs no allocation and no clearing), then a bitset of one bit
/// a primitive, made only for a walk that gets that far.
pub struct Mailbox {
    few: ArrayVec<u32, { Mailbox::FEW }>,
    bits: Vec<u64>,
    primitives: usize,
}

impl Mailbox {
    /// How many primitives the inline list holds.
    pub const FEW: usize = 32;

    /// An empty set for a walk over primitives `0..primitives`.
    pub fn new(primitives: usize) -> Mailbox {
        Mailbox {
            few: ArrayVec::new(),
            bits: Vec::new(),
            primitives,
        }
    }

    /// Whether `p` is new to this walk (and from now on it is not).
    #[inline]
    pub fn first_time(&mut self, p: u32) -> bool {
        if self.bits.is_empty() {
            if self.few.contains(&p) {
                return false;
            }
            if !self.few.is_full() {
                self.few.push(p);
                return true;
            }
            self.bits = vec![0; self.primitives.div_ceil(64)];
            for &q in &self.few {
                self.bits[q as usize / 64] |= 1 << (q % 64);
            }
        }
        let (word, bit) = (p as usize / 64, 1u64 << (p % 64));
        let new = self.bits[word] & bit == 0;
        self.bits[word] |= bit;
        new
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_primitive_is_new_once_past_the_inline_list_too() {
        // 100 primitives, each offered three times in a scrambled order: the
        // first 32 go to the inline list, the rest to the bitset, which must
        // carry the list's marks over (a lost mark would say "new" twice).
        let mut m = Mailbox::new(100);
        let mut firsts = 0;
        for round in 0..3 {
            for k in 0..100u32 {
                let p = (k * 37 + round) % 100;
                firsts += usize::from(m.first_time(p));
            }
        }
        assert_eq!(firsts, 100);
    }
}
