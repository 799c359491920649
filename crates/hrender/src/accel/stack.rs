//! The traversal stack: a few dozen entries inline, which every real
//! hierarchy stays within, and a heap vector past them, so no depth can
//! overflow it, and a ray clears 32 entries instead of an array sized for
//! the deepest tree the build allows (181).

/// Entries kept inline: a four-wide tree over a million leaves is about
/// ten levels deep and pushes at most three entries a level.
const INLINE: usize = 32;

/// A last-in, first-out stack of `T`.
pub(super) struct Stack<T> {
    inline: [T; INLINE],
    spill: Vec<T>,
    len: usize,
}

impl<T: Copy + Default> Stack<T> {
    /// A stack holding `first`.
    #[inline(always)]
    pub fn with(first: T) -> Stack<T> {
        let mut inline = [T::default(); INLINE];
        inline[0] = first;
        Stack {
            inline,
            spill: Vec::new(),
            len: 1,
        }
    }

    #[inline(always)]
    pub fn push(&mut self, x: T) {
        if self.len < INLINE {
            self.inline[self.len] = x;
        } else {
            self.spill.push(x);
        }
        self.len += 1;
    }

    #[inline(always)]
    pub fn pop(&mut self) -> Option<T> {
        if self.len == 0 {
            return None;
        }
        self.len -= 1;
        if self.len < INLINE {
            Some(self.inline[self.len])
        } else {
            self.spill.pop()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Past the inline entries and back, in last-in, first-out order.
    #[test]
    fn spills_and_returns_in_order() {
        let mut s = Stack::with(0u32);
        for i in 1..100 {
            s.push(i);
        }
        for i in (0..100).rev() {
            assert_eq!(s.pop(), Some(i));
        }
        assert_eq!(s.pop(), None);
        s.push(7);
        assert_eq!(s.pop(), Some(7));
    }
}
