//! A `squeezed-netcdf` measurement: the NetCDF-3 file SurfaceTopography
//! writes for it, read as a container's measurement.

use super::{
    netcdf, parameter, unit_metres, yaml, ContainerOptions, Cx, Failure, Heights, Measurement, Spec, META_MAX_BYTES,
};
use crate::topography::Topography;

impl Spec {
    /// A NetCDF data file (SurfaceTopography's `to_netcdf`, see
    /// [`netcdf`]): its own unit and sizes win over the metadata's, as in
    /// SurfaceTopography; its `info`'s instrument parameters are used where
    /// the metadata gives none.
    pub(super) fn read_netcdf(
        &self,
        bytes: &[u8],
        cx: &Cx,
        options: &ContainerOptions,
        at: &str,
    ) -> Result<Measurement, Failure> {
        let bad = |d: String| Failure::Other(cx.archive(format!("{at}: data file {}: {d}", self.data_file)));
        let nc = netcdf::read(bytes, options.read.max_points).map_err(bad)?;
        let unit = match &nc.unit {
            Some(u) => unit_metres("unit", u).map_err(|d| bad(format!("its {d}")))?,
            None => self
                .unit
                .as_ref()
                .map(|u| u.1)
                .ok_or_else(|| Failure::Meta("unit: missing (the data file gives none)".into()))?,
        };
        let sizes = match (&nc.lengths, &self.size) {
            (Some(l), _) => Some(l.clone()),
            (None, Some(s)) => Some(s.clone()),
            (None, None) => None,
        };
        let need_size = || Failure::Meta("size: missing (the data file gives none)".into());
        let topography = |r: Result<Topography, crate::topography::TopographyError>| r.map_err(|e| bad(e.to_string()));
        let scale = |v: Vec<f64>| -> Vec<f64> { v.into_iter().map(|z| z * unit).collect() };
        let heights = match nc.grid {
            netcdf::Grid::Map { nx, ny, heights } => {
                let s = sizes.filter(|s| s.len() == 2).ok_or_else(need_size)?;
                Heights::Uniform(topography(Topography::map(
                    scale(heights),
                    nx,
                    ny,
                    s[0] * unit / nx as f64,
                    s[1] * unit / ny as f64,
                ))?)
            }
            netcdf::Grid::Profile(h) => {
                let s = sizes.filter(|s| s.len() == 1).ok_or_else(need_size)?;
                let n = h.len();
                Heights::Uniform(topography(Topography::profile(scale(h), s[0] * unit / n as f64))?)
            }
            netcdf::Grid::Nonuniform { x, z } => {
                if x.len() < 2 || x.iter().chain(&z).any(|v| !v.is_finite()) {
                    return Err(bad("a nonuniform profile needs 2 or more points, all finite".into()));
                }
                if x.windows(2).any(|w| w[1] <= w[0]) {
                    return Err(bad("the positions x of a nonuniform profile do not increase".into()));
                }
                let x0 = x[0];
                Heights::Nonuniform {
                    x: x.iter().map(|v| (v - x0) * unit).collect(),
                    z: scale(z),
                }
            }
        };
        let (mut tip_radius, mut resolution) = (self.tip_radius, self.resolution);
        if !self.instrument_given {
            if let Some(json) = &nc.json {
                if json.len() as u64 > META_MAX_BYTES {
                    return Err(bad(format!(
                        "its json attribute is {} bytes, over the limit of {META_MAX_BYTES} bytes",
                        json.len()
                    )));
                }
                let info = yaml::parse(json).map_err(|d| bad(format!("its json attribute: {d}")))?;
                let parameters = info.get("instrument").and_then(|i| i.get("parameters"));
                let field = "json.instrument.parameters";
                if let Some(n) = parameters.and_then(|p| p.get("tip_radius")) {
                    tip_radius = Some(parameter(n, &format!("{field}.tip_radius"), Some(unit)).map_err(bad)?);
                    resolution = None;
                } else if let Some(n) = parameters.and_then(|p| p.get("resolution")) {
                    resolution = Some(parameter(n, &format!("{field}.resolution"), Some(unit)).map_err(bad)?);
                    tip_radius = None;
                }
            }
        }
        Ok(self.measurement(heights, self.is_periodic || nc.periodic, tip_radius, resolution))
    }
}
