//! The reference values of MODEL.md §7 and §8 (30-digit quadrature).
use crate::common::{assert_rel, REFERENCE_REL};
use ke_friction::{Model, ModelKind, Params};

/// (ψ, θ, h*, d*, P*, Fs*, Q*, F*, μ) from MODEL.md §7.
const KE_AT_H: [[f64; 9]; 6] = [
    [
        0.5,
        0.003,
        1.0,
        -0.1486018655,
        1.1522898584e-02,
        1.7642859645e-03,
        1.1028662054e-02,
        9.7586126192e-03,
        1.1301465161e+00,
    ],
    [
        1.0,
        0.001,
        2.0,
        0.8513981345,
        3.3988495467e-03,
        1.4693402966e-04,
        1.9370980416e-03,
        3.2519155171e-03,
        5.9567907943e-01,
    ],
    [
        2.0,
        0.0,
        0.5,
        -0.6486018655,
        7.9720740665e-02,
        0.0,
        2.8009985629e-03,
        7.9720740665e-02,
        3.5135129699e-02,
    ],
    [
        2.0,
        0.003,
        3.0,
        1.8513981345,
        3.8818884584e-04,
        4.0297620855e-05,
        9.0502167010e-05,
        3.4789122498e-04,
        2.6014501232e-01,
    ],
    [
        8.0,
        0.0001,
        1.5,
        0.3513981345,
        4.0489423603e-02,
        1.9812879105e-05,
        1.0336997658e-05,
        4.0469610724e-02,
        2.5542616973e-04,
    ],
    [
        1.0,
        0.01,
        0.0,
        -1.1486018655,
        7.6816667238e-02,
        1.1374479790e-02,
        2.5062021158e-02,
        6.5442187448e-02,
        3.8296429467e-01,
    ],
];

/// (ψ, θ, F*, h*, μ) from MODEL.md §7.
const KE_AT_F: [[f64; 5]; 3] = [
    [1.0, 0.001, 0.01, 1.4692414618, 5.2521087083e-01],
    [0.5, 0.01, 0.001, 1.6515021415, 3.9838855827e+00],
    [4.0, 0.0003, 0.05, 1.1505904053, 3.5943724864e-03],
];

/// (ψ, θ, h*, P*, Q*, F*, μ) from MODEL.md §8.
const CEB_AT_H: [[f64; 7]; 3] = [
    [
        0.5,
        0.003,
        1.0,
        1.1528941063e-02,
        6.8333578436e-03,
        9.7646550986e-03,
        6.9980534639e-01,
    ],
    [
        1.0,
        0.0,
        2.0,
        4.4051507593e-03,
        6.9579625128e-04,
        4.4051507593e-03,
        1.5795061039e-01,
    ],
    [
        2.0,
        0.003,
        0.5,
        9.9096463324e-02,
        1.2904972585e-04,
        9.6505293204e-02,
        1.3372295090e-03,
    ],
];

/// (ψ, θ, F*, h*, μ) from MODEL.md §8.
const CEB_AT_F: [[f64; 5]; 3] = [
    [0.5, 0.003, 0.001, 2.0906493680, 1.0474614811e+00],
    [1.0, 0.003, 0.01, 1.6029688916, 1.2586850626e-01],
    [2.0, 0.003, 0.0001, 3.4633463244, 3.0548269102e-02],
];

/// Values printed to 11 significant digits are exact to 5e-11 relative;
/// d* is printed to 10 decimals.
const PRINTED: f64 = 5e-11;

#[test]
fn kogut_etsion_at_h_star_matches_model_md_section_7() {
    for [psi, theta, h, d, p, fs, q, f, mu] in KE_AT_H {
        let c = Model::new(Params::new(psi, theta)).unwrap().at_h_star(h).unwrap();
        let tag = format!("ψ={psi} θ={theta} h*={h}");
        assert!((c.d_star - d).abs() < 1e-10, "{tag}: d* {} vs {d}", c.d_star);
        assert_rel(&format!("{tag} P*"), c.p_star, p, REFERENCE_REL.min(PRINTED));
        assert_rel(&format!("{tag} Fs*"), c.fs_star, fs, REFERENCE_REL.min(PRINTED));
        assert_rel(&format!("{tag} Q*"), c.q_star, q, REFERENCE_REL.min(PRINTED));
        assert_rel(&format!("{tag} F*"), c.f_star, f, REFERENCE_REL.min(PRINTED));
        assert_rel(&format!("{tag} μ"), c.mu.unwrap(), mu, REFERENCE_REL.min(PRINTED));
    }
}

#[test]
fn kogut_etsion_at_f_star_matches_model_md_section_7() {
    for [psi, theta, f, h, mu] in KE_AT_F {
        let c = Model::new(Params::new(psi, theta)).unwrap().at_f_star(f).unwrap();
        let tag = format!("ψ={psi} θ={theta} F*={f}");
        assert!((c.h_star - h).abs() < 1e-10, "{tag}: h* {} vs {h}", c.h_star);
        assert_rel(&format!("{tag} F*"), c.f_star, f, 1e-14);
        assert_rel(&format!("{tag} μ"), c.mu.unwrap(), mu, PRINTED);
    }
}

#[test]
fn ceb_type_matches_model_md_section_8() {
    for [psi, theta, h, p, q, f, mu] in CEB_AT_H {
        let model = Model::new(Params::new(psi, theta).kind(ModelKind::CebType)).unwrap();
        let c = model.at_h_star(h).unwrap();
        let tag = format!("CEB ψ={psi} θ={theta} h*={h}");
        assert_rel(&format!("{tag} P*"), c.p_star, p, PRINTED);
        assert_rel(&format!("{tag} Q*"), c.q_star, q, PRINTED);
        assert_rel(&format!("{tag} F*"), c.f_star, f, PRINTED);
        assert_rel(&format!("{tag} μ"), c.mu.unwrap(), mu, PRINTED);
    }
    for [psi, theta, f, h, mu] in CEB_AT_F {
        let model = Model::new(Params::new(psi, theta).kind(ModelKind::CebType)).unwrap();
        let c = model.at_f_star(f).unwrap();
        let tag = format!("CEB ψ={psi} θ={theta} F*={f}");
        assert!((c.h_star - h).abs() < 1e-10, "{tag}: h* {} vs {h}", c.h_star);
        assert_rel(&format!("{tag} μ"), c.mu.unwrap(), mu, PRINTED);
    }
}
