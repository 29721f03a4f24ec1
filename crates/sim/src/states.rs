//! Unary object states (`cooked`, `open`, `dusty`, ...) as stored truth values with setters.
//!
//! Today these are plain flags that the sampler and tests set; the rules that derive them from
//! physics (temperature, water, particles, slicing force, toggling, joint angles) are the next
//! part of this crate's work (issue 3) and will replace the flags one state at a time.

use behavior_bddl::Predicate;

/// The unary states of one object, one bit per predicate.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct UnaryStates(u32);

impl UnaryStates {
    fn bit(predicate: Predicate) -> Option<u32> {
        (predicate.arity() == 1).then(|| 1 << (predicate as u32))
    }

    pub fn get(self, predicate: Predicate) -> bool {
        Self::bit(predicate).is_some_and(|b| self.0 & b != 0)
    }

    /// Sets a unary state; `false` for a binary predicate, which is not a stored state.
    pub fn set(&mut self, predicate: Predicate, value: bool) -> bool {
        let Some(b) = Self::bit(predicate) else {
            return false;
        };
        if value {
            self.0 |= b;
        } else {
            self.0 &= !b;
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flags_are_independent_and_binary_predicates_are_refused() {
        let mut s = UnaryStates::default();
        assert!(s.set(Predicate::Cooked, true));
        assert!(s.set(Predicate::Open, true));
        assert!(s.set(Predicate::Cooked, false));
        assert!(!s.get(Predicate::Cooked) && s.get(Predicate::Open));
        assert!(!s.set(Predicate::OnTop, true));
        assert!(!s.get(Predicate::OnTop));
    }
}
