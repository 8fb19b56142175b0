//! The plausibility warnings of this thread's calls (the core's
//! `ke_friction::Warning`, one bit a kind): `kef_warnings()` reads the
//! mask, `kef_clear_warnings()` clears it, `kef_warning_message(kind)`
//! formats the latest warning of a kind (only when asked: a call that
//! warns stores its contact, two words, and sets bits).

use ke_friction::{Contact, Params, Warning, WarningKind};
use std::cell::{Cell, RefCell};
use std::ffi::{c_char, c_int, CString};

/// Warning bit: F* below the range the paper covers (1e-5 <= F* <= 0.1):
/// extrapolated; so light a load touches only the highest summits.
pub const KEF_WARN_F_STAR_BELOW_RANGE: c_int = 1 << 0;
/// Warning bit: F* above the paper's range (0.1 < F* <= 1; F* > 1 is
/// KEF_ERR_DOMAIN): extrapolated.
pub const KEF_WARN_F_STAR_ABOVE_RANGE: c_int = 1 << 1;
/// Warning bit: h* < 0 (the mean planes overlap): extrapolated.
pub const KEF_WARN_NEGATIVE_SEPARATION: c_int = 1 << 2;
/// Warning bit: mu > 1: adhesion, not the load, dominates.
pub const KEF_WARN_ADHESION_DOMINATED: c_int = 1 << 3;
/// Warning bit: fewer than 10 asperities in contact (not set by the C
/// API, which knows no area; reserved with the core's list).
pub const KEF_WARN_FEW_ASPERITIES: c_int = 1 << 4;
/// Warning bit: spectral derivatives of a non-periodic surface (the
/// surface statistics; reserved with the core's list).
pub const KEF_WARN_NON_PERIODIC: c_int = 1 << 5;
/// Warning bit: bandwidth alpha < 1.5 (surface statistics; reserved).
pub const KEF_WARN_LOW_BANDWIDTH: c_int = 1 << 6;
/// Warning bit: an anisotropic surface (surface statistics; reserved).
pub const KEF_WARN_ANISOTROPY: c_int = 1 << 7;
/// Warning bit: two surfaces sampled at different intervals (reserved).
pub const KEF_WARN_INTERVAL_MISMATCH: c_int = 1 << 8;
/// Warning bit: scales below the instrument's reliability cut-off
/// (reserved).
pub const KEF_WARN_UNRELIABLE_SCALE: c_int = 1 << 9;

/// Warning bit: psi outside the range the paper covers, 0.5 <= psi <= 8
/// (set by kef_params_from_physical).
pub const KEF_WARN_PSI_DOMAIN: c_int = 1 << 10;
/// Warning bit: theta above the paper's upper limit 0.01 (set by
/// kef_params_from_physical).
pub const KEF_WARN_THETA_DOMAIN: c_int = 1 << 11;
/// Warning bit: beta outside 0.02 <= beta <= 0.16, within a factor 4 of
/// the paper's 0.04 (set by kef_params_from_physical).
pub const KEF_WARN_BETA_DOMAIN: c_int = 1 << 12;
/// Warning bit: spikes in a surface's heights (surface statistics;
/// reserved).
pub const KEF_WARN_SPIKES: c_int = 1 << 13;
/// Warning bit: the contact lies above the measured heights (a measured
/// surface's; reserved).
pub const KEF_WARN_TAIL: c_int = 1 << 14;

/// The C constants in the core's order (a test checks them against
/// `WarningKind::bit`).
pub(crate) const KEF_WARN: [(c_int, WarningKind); 15] = [
    (KEF_WARN_F_STAR_BELOW_RANGE, WarningKind::FStarBelowRange),
    (KEF_WARN_F_STAR_ABOVE_RANGE, WarningKind::FStarAboveRange),
    (KEF_WARN_NEGATIVE_SEPARATION, WarningKind::NegativeSeparation),
    (KEF_WARN_ADHESION_DOMINATED, WarningKind::AdhesionDominated),
    (KEF_WARN_FEW_ASPERITIES, WarningKind::FewAsperities),
    (KEF_WARN_NON_PERIODIC, WarningKind::NonPeriodic),
    (KEF_WARN_LOW_BANDWIDTH, WarningKind::LowBandwidth),
    (KEF_WARN_ANISOTROPY, WarningKind::Anisotropy),
    (KEF_WARN_INTERVAL_MISMATCH, WarningKind::IntervalMismatch),
    (KEF_WARN_UNRELIABLE_SCALE, WarningKind::UnreliableScale),
    (KEF_WARN_PSI_DOMAIN, WarningKind::PsiOutsideDomain),
    (KEF_WARN_THETA_DOMAIN, WarningKind::ThetaOutsideDomain),
    (KEF_WARN_BETA_DOMAIN, WarningKind::BetaOutsideDomain),
    (KEF_WARN_SPIKES, WarningKind::Spikes),
    (KEF_WARN_TAIL, WarningKind::Tail),
];

thread_local! {
    /// The bits set since the last kef_clear_warnings on this thread.
    static MASK: Cell<u32> = const { Cell::new(0) };
    /// The latest contact that warned, per contact kind (its message is
    /// formatted from it on request).
    static LATEST: [Cell<Option<Contact>>; 4] = const { [const { Cell::new(None) }; 4] };
    /// The latest warnings of the model's inputs (the validity domain's:
    /// ψ, θ, β), of the latest call that gave one.
    static DOMAIN: RefCell<Vec<Warning>> = const { RefCell::new(Vec::new()) };
    /// The last message kef_warning_message returned, kept alive until
    /// the next call on the thread.
    static MESSAGE: RefCell<CString> = RefCell::new(CString::default());
}

/// Records the warnings of a contact a call returned: arithmetic, and a
/// store per kind that warned.
pub(crate) fn note(contact: &Contact) {
    let mask = Warning::mask_of_contact(contact);
    if mask == 0 {
        return;
    }
    MASK.with(|m| m.set(m.get() | mask));
    LATEST.with(|latest| {
        for (i, cell) in latest.iter().enumerate() {
            if mask & (1 << i) != 0 {
                cell.set(Some(*contact));
            }
        }
    });
}

/// Records the validity domain's warnings of inputs a call returned
/// ([`Warning::of_params`]).
pub(crate) fn note_params(params: &Params) {
    let warnings: Vec<Warning> = Warning::of_params(params).collect();
    if warnings.is_empty() {
        return;
    }
    let mask = warnings.iter().fold(0, |m, w| m | w.kind().bit());
    MASK.with(|m| m.set(m.get() | mask));
    DOMAIN.with(|d| {
        let mut d = d.borrow_mut();
        d.retain(|old| warnings.iter().all(|w| w.kind() != old.kind()));
        d.extend(warnings);
    });
}

/// The warnings of this thread's calls since the last
/// kef_clear_warnings (or the thread's start): a mask of KEF_WARN_* bits,
/// 0 if none. The direct integrations (kef_model_mu, kef_model_mu_with)
/// set them for a result they return (F* outside 1e-5..0.1, h* < 0,
/// mu > 1), kef_params_from_physical for inputs outside the validity
/// domain (psi, theta, beta); a call that fails sets none.
#[no_mangle]
pub extern "C" fn kef_warnings() -> c_int {
    MASK.with(|m| m.get() as c_int)
}

/// Clears this thread's warnings (kef_warnings() is 0 after it).
#[no_mangle]
pub extern "C" fn kef_clear_warnings() {
    MASK.with(|m| m.set(0));
    LATEST.with(|latest| latest.iter().for_each(|c| c.set(None)));
    DOMAIN.with(|d| d.borrow_mut().clear());
}

/// The message of this thread's latest warning of kind `kind` (one
/// KEF_WARN_* bit), e.g. "F* = 1e-7 is below the range the paper covers
/// ...": formatted by this call. "" when none was recorded since
/// kef_clear_warnings, or `kind` is not one bit the calls set. Never NULL;
/// do not free it; valid until the next kef_warning_message call on the
/// thread.
#[no_mangle]
pub extern "C" fn kef_warning_message(kind: c_int) -> *const c_char {
    let text = KEF_WARN
        .iter()
        .position(|&(bit, _)| bit == kind)
        .and_then(|i| {
            let kind = KEF_WARN[i].1;
            if let Some(w) = DOMAIN.with(|d| d.borrow().iter().find(|w| w.kind() == kind).cloned()) {
                return Some(w);
            }
            let contact = LATEST.with(|latest| latest.get(i).and_then(Cell::get))?;
            Warning::of_contact(&contact).find(|w| w.kind() == kind)
        })
        .map_or_else(String::new, |w| w.to_string());
    MESSAGE.with(|m| {
        let mut m = m.borrow_mut();
        // A message holds no NUL (the core's text); one would end it.
        *m = CString::new(text).unwrap_or_default();
        m.as_ptr()
    })
}
