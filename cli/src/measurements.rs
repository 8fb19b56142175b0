//! `kefric surface --measurements FILE[@KEY=VALUE,...] ...`: loose files
//! as the measurements of one surface, read into the same surface a
//! container of them gives (the library's `container::read_loose`), for
//! `--psd`, `--scan` or μ exactly as for a container (container.rs, which
//! calls this). Two positional files stay two surfaces pressed together.

use crate::output::Failure;
use crate::surface_args::SurfaceArgs;
use ke_friction::topography::container::{
    read_loose, ContainerOptions, ContainerSurface, DetrendMode, LooseMeasurement, LooseOptions,
};
use ke_friction::topography::Detrend;

/// The surface of the loose files `files`, each with its settings, the
/// flags' unit and detrending for the files without their own.
pub fn read(args: &SurfaceArgs, files: &[String], container: ContainerOptions) -> Result<ContainerSurface, Failure> {
    let specs = files
        .iter()
        .map(|f| f.parse::<LooseMeasurement>())
        .collect::<Result<Vec<_>, String>>()
        .map_err(|e| Failure::input(format!("--measurements: {e}")))?;
    if args.z_unit != args.xy_unit {
        return Err(Failure::input(
            "--z-unit, --xy-unit: one unit for a measurement's lengths and heights with --measurements (each file's unit= setting, as a container's meta.yml)",
        ));
    }
    let detrend = match args.detrend {
        Detrend::Plane => DetrendMode::Height,
        Detrend::Mean => DetrendMode::Center,
        Detrend::Line => {
            return Err(Failure::input(
                "--detrend: line is not with --measurements: plane or mean (or each file's detrend_mode=center|height|curvature)",
            ))
        }
    };
    let options = LooseOptions {
        container,
        unit: args.xy_unit,
        detrend,
    };
    read_loose(&specs, &options).map_err(|e| Failure::of("--measurements", e))
}
