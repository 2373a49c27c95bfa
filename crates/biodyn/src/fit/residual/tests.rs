//! The residuals and their adjoint Jacobian against finite differences.
use super::*;
use crate::Solver;
use crate::body::model::{End, Segment};

fn data_all(body: &Body) -> Measured {
    let s = Solver::new(body);
    let mut text = String::from(
        "f_hz,stht_mag,stht_phase_deg,dpmi_mag,dpmi_phase_deg,apms_mag,apms_phase_deg\n",
    );
    for i in 0..40 {
        let f = 0.5 + 0.5 * i as f64;
        let r = s.at(f);
        text += &format!("{f}");
        for fun in Function::ALL {
            text += &format!(",{},{}", r.mag(fun), r.phase_deg(fun));
        }
        text.push('\n');
    }
    Measured::parse(&text, "t").unwrap()
}

/// A branched body: a viscera mass hanging off the chest, so the
/// general (non-chain) path is exercised too.
fn branched() -> Body {
    let mut b = Body::paper(75.0).unwrap();
    b.segments.push(Segment::new("viscera", 4.0));
    b.links.push(crate::Link::new(
        "viscera-chest",
        4,
        End::Segment(1),
        4e4,
        300.0,
    ));
    b.validate().unwrap();
    b
}

#[test]
fn the_start_model_reproduces_its_own_response() {
    for body in [Body::paper(75.0).unwrap(), branched()] {
        let data = data_all(&body);
        let free = [Param::Stiffness(0), Param::Mass(2)];
        let mut e = Engine::new(&body, &data, &free).unwrap();
        let theta: Vec<f64> = free.iter().map(|&p| body.get(p).ln()).collect();
        let mut r = vec![0.0; e.m()];
        let cost = e.eval(&theta, &mut r, None);
        assert!(cost < 1e-20, "{cost}");
    }
}

#[test]
fn analytic_jacobian_matches_central_differences() {
    for body in [Body::paper(75.0).unwrap(), branched()] {
        let data = data_all(&body);
        let mut free: Vec<Param> = (0..body.links.len())
            .flat_map(|i| [Param::Stiffness(i), Param::Damping(i)])
            .collect();
        free.extend([Param::Mass(0), Param::Mass(3)]);
        for with_body_mass in [false, true] {
            let free: Vec<Param> = if with_body_mass {
                let mut f: Vec<Param> = free
                    .iter()
                    .copied()
                    .filter(|p| !matches!(p, Param::Mass(_)))
                    .collect();
                f.push(Param::BodyMass);
                f
            } else {
                free.clone()
            };
            let mut e = Engine::new(&body, &data, &free).unwrap();
            let (m, p) = (e.m(), e.p());
            // Off the data, so the residuals are not zero.
            let theta: Vec<f64> = free
                .iter()
                .enumerate()
                .map(|(j, &q)| body.get(q).ln() + 0.1 * ((j as f64) * 1.7).sin())
                .collect();
            let mut r = vec![0.0; m];
            let mut jac = vec![0.0; m * p];
            e.eval(&theta, &mut r, Some(&mut jac));
            let h = 1e-6;
            for j in 0..p {
                let mut tp = theta.clone();
                let mut tm = theta.clone();
                tp[j] += h;
                tm[j] -= h;
                let (mut rp, mut rm) = (vec![0.0; m], vec![0.0; m]);
                e.eval(&tp, &mut rp, None);
                e.eval(&tm, &mut rm, None);
                for i in 0..m {
                    let mut d = rp[i] - rm[i];
                    if e.entries[i].quantity == Quantity::Phase {
                        d = wrap(d);
                    }
                    let fd = d / (2.0 * h);
                    let an = jac[j * m + i];
                    assert!(
                        (fd - an).abs() <= 1e-6 * (1.0 + an.abs()),
                        "residual {i} parameter {:?}: analytic {an} vs {fd}",
                        free[j]
                    );
                }
            }
        }
    }
}
