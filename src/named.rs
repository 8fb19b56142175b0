//! One vocabulary: the closed sets of named values users type and read
//! (fit, model, distribution family, detrending, derivative, length unit).
//!
//! Each set is an enum with one [`named!`](crate::named) line listing its
//! values and their names: that line gives the enum its `ALL`, `name`,
//! `from_name`, its JSON form and Display, and the [`Named`] trait whose
//! [`Named::parse`] writes the "must be one of …" message once for every
//! front end (the CLI's value parsers, the C ABI's names, Python's).

use std::fmt;

/// A closed set of named values (see the module docs).
pub trait Named: Copy + PartialEq + 'static {
    /// What a value is, in messages: `"fit"`, `"model"`, `"detrend"`, …
    const WHAT: &'static str;

    /// Every value, in the documented order.
    fn all() -> &'static [Self];

    /// The value's name where users type or read it.
    fn name(self) -> &'static str;

    /// Every name, in order.
    fn names() -> Vec<&'static str> {
        Self::all().iter().map(|v| v.name()).collect()
    }

    /// The value called `name` (exactly as [`Named::name`] spells it), or
    /// an error naming the valid names.
    ///
    /// ```
    /// use ke_friction::{Fit, Named};
    /// assert_eq!(Fit::parse("as-printed")?, Fit::AsPrinted);
    /// assert_eq!(
    ///     Fit::parse("loose").unwrap_err().to_string(),
    ///     "fit 'loose' is unknown: must be one of consistent, as-printed"
    /// );
    /// # Ok::<(), ke_friction::NameError>(())
    /// ```
    fn parse(name: &str) -> Result<Self, NameError> {
        Self::all()
            .iter()
            .copied()
            .find(|v| v.name() == name)
            .ok_or_else(|| NameError::new(Self::WHAT, name, Self::names()))
    }
}

/// A name that is not one of its set's.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NameError {
    /// What was named (`"fit"`, …).
    pub what: &'static str,
    /// The name given (at most 40 characters of it).
    pub given: String,
    /// The valid names.
    pub names: Vec<String>,
}

impl NameError {
    /// `given` is not one of `names` (what a set not written by
    /// `named!` uses, to word it as every other: the web
    /// page's option keys, the CLI's own switches); `given` is cut to 40
    /// characters.
    pub fn new<S: Into<String>>(what: &'static str, given: &str, names: impl IntoIterator<Item = S>) -> NameError {
        NameError {
            what,
            given: given.chars().take(40).collect(),
            names: names.into_iter().map(Into::into).collect(),
        }
    }
}

impl fmt::Display for NameError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} '{}' is unknown: must be one of {}",
            self.what,
            self.given,
            self.names.join(", ")
        )
    }
}

impl std::error::Error for NameError {}

/// An unknown name is the caller's argument.
impl crate::Classify for NameError {
    fn kind(&self) -> crate::ErrorKind {
        crate::ErrorKind::Argument
    }
}

/// Gives an enum of unit variants its names, once: `ALL`, `name`,
/// `from_name`, [`Named`], `Display` and `Serialize` (as its name).
///
/// ```ignore
/// named!(Detrend, "detrend", [Plane = "plane", Line = "line", Mean = "mean"]);
/// ```
#[macro_export]
#[doc(hidden)]
macro_rules! named {
    // An entry after the first may carry a `#[cfg(...)]` (a test-only
    // value): it is then left out of `ALL` and `name` alike.
    ($ty:ident, $what:literal, [$first:ident = $first_name:literal
        $(, $(#[cfg($cfg:meta)])? $variant:ident = $name:literal)* $(,)?]) => {
        impl $ty {
            /// How many values there are (those configured in).
            const COUNT: usize = {
                let mut n = 1;
                $( $(#[cfg($cfg)])? { n += 1; } )*
                n
            };

            /// Every value, in the documented order.
            pub const ALL: [$ty; Self::COUNT] = {
                let mut all = [$ty::$first; Self::COUNT];
                let mut i = 1;
                $( $(#[cfg($cfg)])? { all[i] = $ty::$variant; i += 1; } )*
                let _ = i;
                all
            };

            /// The name users type and read (CLI flags, JSON, the bindings).
            pub const fn name(self) -> &'static str {
                match self {
                    $ty::$first => $first_name,
                    $( $(#[cfg($cfg)])? $ty::$variant => $name, )*
                }
            }
        }
        $crate::named!(@common $ty, $what);
    };
    // The values and names from a registry: a `const` array of entries
    // with fields `kind` (the value) and `name`, in the enum's order
    // (checked at compile time).
    ($ty:ident, $what:literal, registry = $table:path) => {
        const _: () = {
            let mut i = 0;
            while i < $table.len() {
                assert!($table[i].kind as usize == i, "the registry is not in the enum's order");
                i += 1;
            }
        };

        impl $ty {
            /// Every value, in the documented order.
            pub const ALL: [$ty; $table.len()] = {
                let mut all = [$table[0].kind; $table.len()];
                let mut i = 1;
                while i < $table.len() {
                    all[i] = $table[i].kind;
                    i += 1;
                }
                all
            };

            /// The name users type and read (CLI flags, JSON, the bindings).
            pub const fn name(self) -> &'static str {
                $table[self as usize].name
            }
        }
        $crate::named!(@common $ty, $what);
    };
    (@common $ty:ident, $what:literal) => {
        impl $ty {
            /// The value named `name` (exactly as `name()` spells it), if any;
            /// [`Named::parse`](crate::Named::parse) gives an error instead.
            pub fn from_name(name: &str) -> Option<$ty> {
                <$ty as $crate::Named>::parse(name).ok()
            }
        }

        impl $crate::Named for $ty {
            const WHAT: &'static str = $what;

            fn all() -> &'static [$ty] {
                &$ty::ALL
            }

            fn name(self) -> &'static str {
                $ty::name(self)
            }
        }

        impl ::std::fmt::Display for $ty {
            fn fmt(&self, f: &mut ::std::fmt::Formatter<'_>) -> ::std::fmt::Result {
                f.write_str(self.name())
            }
        }

        impl ::serde::Serialize for $ty {
            /// As its name.
            fn serialize<S: ::serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                s.serialize_str(self.name())
            }
        }
    };
}

/// A unit of length heights and intervals are given in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LengthUnit {
    /// Kilometres.
    Km,
    /// Metres.
    M,
    /// Centimetres.
    Cm,
    /// Millimetres.
    Mm,
    /// Micrometres.
    Um,
    /// Nanometres.
    Nm,
    /// Picometres.
    Pm,
    /// Ångström (1e-10 m).
    Angstrom,
}

crate::named!(
    LengthUnit,
    "length unit",
    [
        Km = "km",
        M = "m",
        Cm = "cm",
        Mm = "mm",
        Um = "um",
        Nm = "nm",
        Pm = "pm",
        Angstrom = "angstrom"
    ]
);

impl LengthUnit {
    /// Metres per unit.
    pub const fn metres(self) -> f64 {
        match self {
            LengthUnit::Km => 1e3,
            LengthUnit::M => 1.0,
            LengthUnit::Cm => 1e-2,
            LengthUnit::Mm => 1e-3,
            LengthUnit::Um => 1e-6,
            LengthUnit::Nm => 1e-9,
            LengthUnit::Pm => 1e-12,
            LengthUnit::Angstrom => 1e-10,
        }
    }

    /// The other spellings of the units a file or a SurfaceTopography
    /// object may give (µ as the micro sign or the Greek letter, or as old
    /// code pages' `~m` and `æm`; Å or A), beside the names.
    pub const SYMBOLS: [(&'static str, LengthUnit); 6] = [
        ("\u{b5}m", LengthUnit::Um),
        ("\u{3bc}m", LengthUnit::Um),
        ("~m", LengthUnit::Um),
        ("\u{e6}m", LengthUnit::Um),
        ("\u{c5}", LengthUnit::Angstrom),
        ("A", LengthUnit::Angstrom),
    ];

    /// The unit called `text` (surrounding spaces ignored): one of the
    /// names (`um`) or of the [`SYMBOLS`](Self::SYMBOLS) (`µm`), or an
    /// error listing the names.
    ///
    /// ```
    /// use ke_friction::LengthUnit;
    /// assert_eq!(LengthUnit::from_symbol("\u{b5}m")?, LengthUnit::Um);
    /// assert_eq!(LengthUnit::from_symbol("nm")?.metres(), 1e-9);
    /// assert!(LengthUnit::from_symbol("inch").is_err());
    /// # Ok::<(), ke_friction::NameError>(())
    /// ```
    pub fn from_symbol(text: &str) -> Result<LengthUnit, crate::NameError> {
        let text = text.trim();
        match Self::SYMBOLS.iter().find(|(s, _)| *s == text) {
            Some(&(_, unit)) => Ok(unit),
            None => <LengthUnit as crate::Named>::parse(text),
        }
    }
}
