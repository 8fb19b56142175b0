//! The registry of contact laws: one line a law, giving its
//! [`ModelKind`] variant and its [`LawInfo`] in [`LAWS`] (its name, its
//! table code, its label). A leaf: the
//! parameters, the table format, the figures and every front end read it,
//! and it reads nothing of theirs.

/// Writes [`ModelKind`] and [`LAWS`] from one line a law: its variant
/// (with the variant's documentation), its name, its table code, its
/// label and its type (in `laws/`). The first line is the default.
macro_rules! registry {
    ($($(#[doc = $doc:literal])* $variant:ident = ($name:literal, $code:literal, $label:literal) => $module:ident :: $law:ident),+ $(,)?) => {
        /// Which surface friction model to evaluate: which single-asperity
        /// contact law the surface integrals use (one line each in
        /// `src/model/laws/registry.rs`, docs/ARCHITECTURE.md).
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum ModelKind {
            $($(#[doc = $doc])* $variant),+
        }

        /// Every law, in the order of [`ModelKind`]'s variants.
        pub const LAWS: [LawInfo; [$($name),+].len()] = [
            $(LawInfo { kind: ModelKind::$variant, name: $name, code: $code, label: $label }),+
        ];

        /// The laws' modules, variants and types, for `laws/mod.rs`: it
        /// declares the modules and writes the planned [`Law`](super::Law)
        /// with `laws!`. The paths are tokens here, resolved there: this
        /// file stays a leaf.
        macro_rules! registered_laws {
            () => {
                $(pub mod $module;)+
                laws! { $($variant => $module::$law),+ }
            };
        }
        pub(super) use registered_laws;
    };
}

registry! {
    /// Kogut & Etsion (2004), MODEL.md §4.
    KogutEtsion = ("ke", 0, "Kogut–Etsion") => ke::KogutEtsion,
    /// The CEB-type comparison model, an approximate reconstruction of
    /// Chang, Etsion & Bogy (1988) in the same statistical framework
    /// (MODEL.md §8). Its adhesion term is the Kogut–Etsion one; the
    /// [`Fit`](crate::Fit) setting does not apply to it.
    CebType = ("ceb", 1, "CEB-type (approx.)") => ceb::CebType,
}

/// The first law of the registry: Kogut–Etsion.
impl Default for ModelKind {
    fn default() -> ModelKind {
        LAWS[0].kind
    }
}

crate::named!(ModelKind, "model", registry = LAWS);

impl ModelKind {
    /// The law's registry entry (name, table code, label): read by the
    /// table writer and the figures.
    #[cfg(any(feature = "builder", feature = "plot", test))]
    pub(crate) const fn law(self) -> LawInfo {
        LAWS[self as usize]
    }

    /// The value stored as `code` in a table file's header, if any.
    pub(crate) fn from_code(code: u8) -> Option<ModelKind> {
        LAWS.iter().find(|l| l.code == code).map(|l| l.kind)
    }
}

/// One law's registry entry: what front ends, tables and figures call it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LawInfo {
    /// The variant of [`ModelKind`] (the registry is in the enum's order).
    pub kind: ModelKind,
    /// The name users type and read (`--model`, JSON, the bindings).
    pub name: &'static str,
    /// The model code stored in a table file's header (never reuse one).
    pub code: u8,
    /// The curve label in the comparison figures.
    pub label: &'static str,
}
