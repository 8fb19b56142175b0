//! The model's validity domain, the spikes and the tail warnings and the
//! default height model (issue 48; docs/MODEL.md, "Validity domain" and
//! "The default height model") on the README's synthetic map and on the
//! instruments' files (`$KEF_TOPOGRAPHIES`, else `../shared/topographies`
//! beside the repository; each test passes when they are absent).

use ke_friction::topography::{read_file, ReadOptions, StatsOptions, Surface, SurfaceModel, Topography};
use ke_friction::{Family, Load, Materials, Named, WarningKind};

/// The README's synthetic map (`examples/rough_surface.rs`, 256², σ = 0.5 µm).
pub fn readme_surface() -> Topography {
    crate::rough::surface(crate::rough::N).unwrap()
}

/// The README's aluminium pin on a nickel-coated disk.
const ALUMINIUM: Materials = Materials::from_array([70e9, 0.33, 200e9, 0.31, 1e9, 0.5, 0.4e-9]);
/// Steel on steel (issue 48).
const STEEL: Materials = Materials::from_array([200e9, 0.3, 200e9, 0.3, 2e9, 0.3, 0.4e-9]);

fn file(name: &str) -> Option<Surface> {
    let path = crate::common::instrument_file(name)?;
    let t = read_file(&path, &ReadOptions::default()).unwrap();
    Some(Surface::new(t, StatsOptions::default()).unwrap())
}

/// The kinds of every warning of `surface` with `family` at `force` on 1e-5 m².
fn kinds(surface: &Surface, materials: Materials, family: Option<&str>, force: f64) -> Vec<&'static str> {
    let how = SurfaceModel {
        family: family.map(|f| ke_friction::Family::parse(f).unwrap()),
        ..SurfaceModel::new(materials)
    };
    let e = surface.evaluate(&how, &[Load::Force { force, area: 1e-5 }]).unwrap();
    let mut all = ke_friction::Warnings::new();
    all.extend(surface.stats().warnings.iter().cloned());
    e.note_into(&mut all);
    all.summaries().map(|s| s.worst.kind().name()).collect()
}

#[test]
fn the_readme_example_gives_no_validity_spike_or_tail_warning() {
    let s = Surface::new(readme_surface(), StatsOptions::default()).unwrap();
    assert_eq!(s.default_family(), Family::Pearson);
    let k = kinds(&s, ALUMINIUM, None, 10.0);
    for kind in ["psi_domain", "theta_domain", "beta_domain", "spikes", "tail"] {
        assert!(!k.contains(&kind), "{kind} in {k:?}");
    }
    assert!(k.is_empty(), "{k:?}");
    // and it is close: 2.92 sigma against a highest height of 2.97 sigma.
    let tail = s.stats().tail.as_ref().unwrap();
    assert!(tail.max() > 2.9 && tail.max() < 3.1, "{}", tail.max());
}

#[test]
fn di_1_is_outside_the_validity_domain() {
    let Some(s) = file("di-1.di") else { return };
    let k = kinds(&s, STEEL, None, 1.0);
    assert!(k.contains(&"psi_domain") && k.contains(&"beta_domain"), "{k:?}");
    let how = SurfaceModel::new(STEEL);
    let e = s.evaluate(&how, &[]).unwrap();
    let psi = e
        .domain
        .iter()
        .find(|w| w.kind() == WarningKind::PsiOutsideDomain)
        .unwrap();
    assert!(psi.to_string().starts_with("psi = 209."), "{psi}");
}

#[test]
fn sur_2_has_spikes_and_falls_back_to_the_empirical_density() {
    let Some(s) = file("sur-2.sur") else { return };
    let spikes = s.stats().warnings.iter().find(|w| w.kind() == WarningKind::Spikes);
    let spikes = spikes.expect("a spikes warning");
    assert!(spikes.to_string().contains("kurtosis 811"), "{spikes}");
    assert!(spikes.to_string().contains("clean the data"), "{spikes}");
    // Pearson refuses Sk = -15.6: the default is the empirical density.
    assert_eq!(s.default_family(), Family::Empirical);
    assert!(kinds(&s, STEEL, None, 1.0).contains(&"spikes"));
}

#[test]
fn plu_1_pearson_at_a_light_load_is_on_an_extrapolated_tail() {
    let Some(s) = file("plu-1.plu") else { return };
    let tail = s.stats().tail.as_ref().unwrap();
    let k = kinds(&s, STEEL, Some("pearson"), 0.01);
    assert!(k.contains(&"tail"), "{k:?}");
    let how = SurfaceModel {
        family: Some(ke_friction::Family::Pearson),
        ..SurfaceModel::new(STEEL)
    };
    let e = s
        .evaluate(
            &how,
            &[Load::Force {
                force: 0.01,
                area: 1e-5,
            }],
        )
        .unwrap();
    let w = e.warnings[0].iter().find(|w| w.kind() == WarningKind::Tail).unwrap();
    let text = w.to_string();
    assert!(text.contains("h* = 16.09"), "{text}");
    assert!(
        text.contains(&format!("{:.4}", tail.max())[..4]),
        "{text} {}",
        tail.max()
    );
    assert!(text.contains("0 measured points above"), "{text}");
    // The default is the empirical density here (Pearson's tail is not
    // supported), and its contact has measured heights above it.
    assert_eq!(s.default_family(), Family::Empirical);
    let excess = s.pearson_tail_excess().unwrap().unwrap();
    assert!(excess >= 1.0, "{excess}");
    assert!(!kinds(&s, STEEL, None, 0.01).contains(&"tail"));
}

/// The measurements of docs/MODEL.md: the default family and Pearson's
/// expected count above the highest measured height, on every file.
#[test]
fn the_default_family_of_each_file() {
    let want = [
        ("al3d-1.al3d", "pearson"),
        ("di-1.di", "pearson"),
        ("di-3.di", "empirical"),
        ("metropro-1.dat", "empirical"),
        ("nid-1.nid", "empirical"),
        ("opd-1.opd", "empirical"),
        ("plu-1.plu", "empirical"),
        ("sur-2.sur", "empirical"),
    ];
    for (name, family) in want {
        let Some(s) = file(name) else { return };
        let t = s.stats().tail.as_ref().unwrap();
        println!(
            "{name}: K = {:.3}, Sk = {:.3}, N = {}, z_max = {:.3}, beyond 6 sigma = {}, pearson N.P(z > z_max + 3) = {:?}, default {}",
            s.stats().kurtosis,
            s.stats().skewness,
            s.stats().points,
            t.max(),
            t.beyond(),
            s.pearson_tail_excess(),
            s.default_family()
        );
        assert_eq!(s.default_family().name(), family, "{name}");
    }
    let readme = Surface::new(readme_surface(), StatsOptions::default()).unwrap();
    println!(
        "readme: z_max = {:.3}, pearson N.P(z > z_max + 3) = {:?}",
        readme.stats().tail.as_ref().unwrap().max(),
        readme.pearson_tail_excess()
    );
}
