//! What only one machine has, carried through the common interface
//! without the interface knowing that machine: MINASEC-U's front-panel
//! commands and its panel, the IO86A's second device, each machine's own
//! program and operand errors. The machine that made a value reads it back
//! as its own type ([`Own::get`]); everyone else can compare, copy, print
//! and record it. So `plc/` imports no machine, and a new machine brings
//! its own commands and errors in its own folder.

use std::any::Any;
use std::fmt;
use std::sync::Arc;

/// A value of one machine's own type: comparable, printable, shareable.
pub trait OwnValue: Any + fmt::Debug + fmt::Display + Send + Sync {
    /// Whether `other` is the same type and equal.
    fn same(&self, other: &dyn OwnValue) -> bool;
    /// The value as [`Any`], to read it back as its type.
    fn as_any(&self) -> &dyn Any;
}

impl<T: Any + fmt::Debug + fmt::Display + PartialEq + Send + Sync> OwnValue for T {
    fn same(&self, other: &dyn OwnValue) -> bool {
        other.as_any().downcast_ref::<T>() == Some(self)
    }

    fn as_any(&self) -> &dyn Any {
        self
    }
}

/// One machine's own value (a command, a front, an error), shared: a
/// copy is a reference count.
#[derive(Clone)]
pub struct Own(Arc<dyn OwnValue>);

impl Own {
    /// Wraps `value`.
    pub fn new<T: OwnValue>(value: T) -> Own {
        Own(Arc::new(value))
    }

    /// The value as `T`, if it is one.
    pub fn get<T: Any>(&self) -> Option<&T> {
        self.0.as_any().downcast_ref::<T>()
    }
}

impl PartialEq for Own {
    fn eq(&self, other: &Own) -> bool {
        self.0.same(other.0.as_ref())
    }
}

impl Eq for Own {}

impl fmt::Debug for Own {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.fmt(f)
    }
}

impl fmt::Display for Own {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&*self.0, f)
    }
}

#[cfg(test)]
mod tests {
    use super::Own;

    #[derive(Debug, PartialEq)]
    struct Knob(u8);

    impl std::fmt::Display for Knob {
        fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
            write!(f, "knob {}", self.0)
        }
    }

    #[test]
    fn an_own_value_reads_back_as_its_type_and_compares_by_value() {
        let a = Own::new(Knob(3));
        assert_eq!(a.get::<Knob>(), Some(&Knob(3)));
        assert_eq!(a.get::<String>(), None);
        assert_eq!(a, Own::new(Knob(3)));
        assert_ne!(a, Own::new(Knob(4)));
        assert_ne!(a, Own::new("knob 3".to_string()));
        assert_eq!(a.to_string(), "knob 3");
    }
}
