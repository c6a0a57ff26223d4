//! The ambient conditions of a heat balance: air temperature, wind, elevation and the sun.

/// Which clear-sky model gives the direct solar radiation (IEEE Std 738-2012 table 4 and eq. (18)).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Atmosphere {
    /// clear atmosphere
    Clear,
    /// industrial (polluted) atmosphere
    Industrial,
}

/// The position of the sun relative to the line, and the sky.
#[derive(Clone, Debug, PartialEq)]
pub struct Sun {
    /// latitude of the line `Lat` [deg], north positive
    pub latitude_deg: f64,
    /// day of the year `N` (1 = 1 January) [-]
    pub day_of_year: f64,
    /// local solar time [h] (12 = solar noon)
    pub solar_hour: f64,
    /// azimuth of the line's axis `Z_l` [deg], clockwise from north (90: an east-west line)
    pub line_azimuth_deg: f64,
    /// IEEE 738 clear-sky model
    pub atmosphere: Atmosphere,
    /// CIGRE TB 601 clearness ratio `N_s` [-] (1 for a clean sky, 0.5 for an industrial one; eq. (19))
    pub clearness_ratio: f64,
    /// ground albedo `F` [-] (CIGRE TB 601: about 0.1 for rural ground, 0.6-0.8 for snow)
    pub albedo: f64,
    /// measured global horizontal radiation [W/m^2], which replaces the computed one where the standard
    /// allows it (CIGRE TB 601 section 3.3)
    pub measured_global_w_per_m2: Option<f64>,
}

/// Weather at the conductor.
#[derive(Clone, Debug, PartialEq)]
pub struct Weather {
    /// ambient air temperature `T_a` [K]
    pub air_temperature_k: f64,
    /// wind speed `V_w` [m/s]
    pub wind_speed_m_per_s: f64,
    /// angle between the wind direction and the conductor's axis `phi` [deg] (90: perpendicular)
    pub wind_angle_deg: f64,
    /// elevation of the conductor above sea level `H_e` [m]
    pub elevation_m: f64,
    /// the sun; `None` at night (no solar heating)
    pub sun: Option<Sun>,
}
