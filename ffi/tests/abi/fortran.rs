//! The Fortran module against the header: every C function has an
//! interface of the same name, bound to it, with as many arguments.

use std::collections::BTreeMap;

/// The function prototypes of a C header: name → number of arguments.
fn c_functions(header: &str) -> BTreeMap<String, usize> {
    let mut text = String::new();
    let mut rest = header;
    while let Some(start) = rest.find("/*") {
        text.push_str(&rest[..start]);
        rest = rest[start..].split_once("*/").map_or("", |(_, after)| after);
    }
    text.push_str(rest);
    let code: String = text
        .lines()
        .map(str::trim)
        .filter(|l| !l.starts_with("//") && !l.starts_with('#'))
        .collect::<Vec<_>>()
        .join(" ");
    let mut functions = BTreeMap::new();
    for statement in code.split(';') {
        let Some((before, after)) = statement.split_once('(') else {
            continue;
        };
        let name: String = before
            .chars()
            .rev()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect::<String>()
            .chars()
            .rev()
            .collect();
        if !name.starts_with("kef_") {
            continue;
        }
        let args = after.rsplit_once(')').expect("a closing parenthesis").0.trim();
        let count = if args.is_empty() || args == "void" {
            0
        } else {
            args.split(',').count()
        };
        assert!(functions.insert(name.clone(), count).is_none(), "{name} twice");
    }
    functions
}

/// The interfaces of a Fortran module bound to C: bound name → (Fortran
/// name, number of arguments).
fn fortran_interfaces(module: &str) -> BTreeMap<String, (String, usize)> {
    let mut statements = Vec::new();
    let mut current = String::new();
    for line in module.lines() {
        let code = line.split('!').next().unwrap_or("").trim();
        let code = code.strip_prefix('&').unwrap_or(code);
        match code.strip_suffix('&') {
            Some(head) => current.push_str(head),
            None => {
                current.push_str(code);
                statements.push(std::mem::take(&mut current).to_lowercase());
            }
        }
    }
    let mut interfaces = BTreeMap::new();
    for s in statements {
        let Some((_, bound)) = s.split_once("bind(c, name=\"") else {
            continue;
        };
        let bound = bound.split('"').next().unwrap().to_string();
        let head = s
            .strip_prefix("function ")
            .or_else(|| s.strip_prefix("subroutine "))
            .unwrap_or_else(|| panic!("not a function or subroutine: {s}"));
        let (name, args) = head.split_once('(').unwrap();
        let args = args.split_once(')').unwrap().0.trim();
        let count = if args.is_empty() { 0 } else { args.split(',').count() };
        assert!(
            interfaces
                .insert(bound.clone(), (name.trim().to_string(), count))
                .is_none(),
            "{bound} twice"
        );
    }
    interfaces
}

#[test]
fn every_c_function_has_a_fortran_interface_with_as_many_arguments() {
    let dir = env!("CARGO_MANIFEST_DIR");
    let header = std::fs::read_to_string(format!("{dir}/include/kefriction.h")).unwrap();
    let module = std::fs::read_to_string(format!("{dir}/fortran/ke_friction.f90")).unwrap();
    let c = c_functions(&header);
    let fortran = fortran_interfaces(&module);
    assert!(c.len() >= 35, "{c:?}");
    assert_eq!(c["kef_table_mu_with_slope_batch_nan"], 8);
    assert_eq!(c["kef_last_error"], 0);
    let mut problems = Vec::new();
    for (name, &count) in &c {
        match fortran.get(name) {
            None => problems.push(format!("{name}: no interface with bind(c, name=\"{name}\")")),
            Some((f_name, _)) if f_name != name => problems.push(format!("{name}: its interface is named {f_name}")),
            Some((_, f_count)) if *f_count != count => {
                problems.push(format!("{name}: {count} arguments in C, {f_count} in Fortran"))
            }
            Some(_) => {}
        }
    }
    for name in fortran.keys().filter(|n| n.starts_with("kef_") && !c.contains_key(*n)) {
        problems.push(format!("{name}: a Fortran interface to no C function"));
    }
    assert!(
        problems.is_empty(),
        "ffi/fortran/ke_friction.f90:\n{}",
        problems.join("\n")
    );
}
