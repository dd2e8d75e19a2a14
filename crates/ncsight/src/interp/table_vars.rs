//! The machine's tables as custom macro system variables (issue 35): the tool offsets and the
//! work offsets a programme reads and writes with `#2001`, `#5221`, `#10001`, ... on the FANUC
//! profiles (tool compensation memory C). The layout is FANUC's as recalled (the 0i-F manual was
//! not at hand; the work offset numbers agree with a secondary list): docs/commands/macros.md.
//!
//! Lathe (X a diameter, as the offset screen shows it), offset n:
//! - wear X #2000+n, Z #2100+n, R #2200+n, tip #2300+n (n up to 64), Y #2400+n (up to 49);
//! - geometry X #2700+n, Z #2800+n, R #2900+n, Y #2450+n (up to 49);
//! - any n up to 999: wear X #10000+n, Z #11000+n, R #12000+n, tip #13000+n, Y #14000+n,
//!   geometry X #15000+n, Z #16000+n, R #17000+n, Y #19000+n.
//!
//! Machining centre, offset n: H wear #2000+n, H geometry #2200+n, D wear #2400+n, D geometry
//! #2600+n (n up to 200); any n up to 999: #10000+n, #11000+n, #12000+n, #13000+n.
//!
//! Work offsets, axis k of the machine's axes in order (X Z on a lathe, X Y Z on a mill, or the
//! setup's `[machine] axes`): external #5200+k, G54 #5220+k, ... G59 #5320+k; G54.1 Pp
//! #7000+20(p-1)+k where the profile has G54.1.

use super::frame::{TableWrite, Tables};
use crate::motion::Vec3;
use crate::profile::{MachineKind, Profile};
use crate::setup::Offset;

/// One value of an offset table entry.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Field {
    WearX,
    WearY,
    WearZ,
    WearR,
    Tip,
    GeometryX,
    GeometryY,
    GeometryZ,
    GeometryR,
    /// Machining centre: H (length) and D (radius), wear and geometry.
    WearLength,
    Length,
}

/// What a system variable number names in the tables.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Slot {
    Offset(u32, Field),
    /// Work offset 0 (external) or 1-6 (G54-G59), axis letter.
    Work(usize, u8),
}

/// The lathe's short ranges: (first number - 1, field, how many offsets).
const LATHE_SHORT: [(i64, Field, u32); 9] = [
    (2000, Field::WearX, 64),
    (2100, Field::WearZ, 64),
    (2200, Field::WearR, 64),
    (2300, Field::Tip, 64),
    (2400, Field::WearY, 49),
    (2450, Field::GeometryY, 49),
    (2700, Field::GeometryX, 64),
    (2800, Field::GeometryZ, 64),
    (2900, Field::GeometryR, 64),
];
const LATHE_LONG: [(i64, Field); 9] = [
    (10000, Field::WearX),
    (11000, Field::WearZ),
    (12000, Field::WearR),
    (13000, Field::Tip),
    (14000, Field::WearY),
    (15000, Field::GeometryX),
    (16000, Field::GeometryZ),
    (17000, Field::GeometryR),
    (19000, Field::GeometryY),
];
const MILL_SHORT: [(i64, Field, u32); 4] =
    [(2000, Field::WearLength, 200), (2200, Field::Length, 200), (2400, Field::WearR, 200), (2600, Field::GeometryR, 200)];
const MILL_LONG: [(i64, Field); 4] = [(10000, Field::WearLength), (11000, Field::Length), (12000, Field::WearR), (13000, Field::GeometryR)];

/// The table slot of variable `number` on this profile's machine, if it is one.
fn slot(profile: &Profile, axes: &[u8], number: i64) -> Option<Slot> {
    let lathe = profile.kind == MachineKind::Lathe;
    // G54.1 P1-P48: #7001 + 20 (P - 1) + k - 1, system 6 + P.
    if (7001..=7960).contains(&number) && profile.has(crate::profile::GFn::AdditionalWorkOffset) {
        let (system, k) = (7 + (number - 7001) / 20, (number - 7001) % 20);
        let letter = *axes.get(usize::try_from(k).ok()?)?;
        return matches!(letter, b'X' | b'Y' | b'Z').then_some(Slot::Work(system as usize, letter));
    }
    if (5201..=5340).contains(&number) {
        let (system, k) = ((number - 5201) / 20, (number - 5201) % 20);
        let letter = *axes.get(usize::try_from(k).ok()?)?;
        return matches!(letter, b'X' | b'Y' | b'Z').then_some(Slot::Work(system as usize, letter));
    }
    let short: &[(i64, Field, u32)] = if lathe { &LATHE_SHORT } else { &MILL_SHORT };
    for &(base, field, count) in short {
        if number > base && number <= base + i64::from(count) {
            return Some(Slot::Offset((number - base) as u32, field));
        }
    }
    let long: &[(i64, Field)] = if lathe { &LATHE_LONG } else { &MILL_LONG };
    long.iter()
        .find(|(base, _)| number > *base && number <= base + crate::setup::MAX_OFFSET_NUMBER as i64)
        .map(|&(base, field)| Slot::Offset((number - base) as u32, field))
}

/// The field of an offset entry, as the offset screen shows it (X a diameter on a lathe).
fn get(o: &Offset, field: Field, x_scale: f64) -> f64 {
    match field {
        Field::WearX => o.wear_x_mm * x_scale,
        Field::WearY => o.wear_y_mm,
        Field::WearZ => o.wear_z_mm,
        Field::WearR => o.wear_radius_mm,
        Field::Tip => f64::from(o.tip),
        Field::GeometryX => o.x_mm * x_scale,
        Field::GeometryY => o.y_mm,
        Field::GeometryZ => o.z_mm,
        Field::GeometryR => o.radius_mm,
        Field::WearLength => o.wear_length_mm,
        Field::Length => o.length_mm,
    }
}

fn set(o: &mut Offset, field: Field, v: f64, x_scale: f64) -> Result<(), String> {
    match field {
        Field::WearX => o.wear_x_mm = v / x_scale,
        Field::WearY => o.wear_y_mm = v,
        Field::WearZ => o.wear_z_mm = v,
        Field::WearR => o.wear_radius_mm = v,
        Field::Tip if v.fract() == 0.0 && (0.0..=9.0).contains(&v) => o.tip = v as u8,
        Field::Tip => return Err(format!("{v}: the imaginary tool tip is a whole number 0 to 9")),
        Field::GeometryX => o.x_mm = v / x_scale,
        Field::GeometryY => o.y_mm = v,
        Field::GeometryZ => o.z_mm = v,
        Field::GeometryR => o.radius_mm = v,
        Field::WearLength => o.wear_length_mm = v,
        Field::Length => o.length_mm = v,
    }
    Ok(())
}

/// The X of the tables is a radius on a lathe; the variables show a diameter.
fn x_scale(profile: &Profile) -> f64 {
    if profile.diameter_x {
        2.0
    } else {
        1.0
    }
}

/// The profiles whose macro variables name the tables (FANUC custom macro B).
fn has_table_variables(profile: &Profile) -> bool {
    profile.macros.table_variables
}

impl Tables {
    /// The value of system variable `number` where it names a table entry: `Some(value)`
    /// (an offset the setup does not give reads 0, as the controller's empty table), else `None`.
    pub fn variable(&self, profile: &Profile, number: i64) -> Option<f64> {
        if !has_table_variables(profile) {
            return None;
        }
        let scale = x_scale(profile);
        Some(match slot(profile, &self.axis_order, number)? {
            Slot::Offset(n, field) => self.offset(n).map_or(0.0, |o| get(o, field, scale)),
            Slot::Work(system, letter) => {
                let p = self.work_mm[system];
                let i = usize::from(letter - b'X');
                p.axis(i) * if i == 0 { scale } else { 1.0 }
            }
        })
    }

    /// The table write that setting system variable `number` to `value` makes, where it names a
    /// table entry (`None` otherwise); an impossible value is the error's text.
    pub fn variable_write(&self, profile: &Profile, number: i64, value: f64) -> Option<Result<TableWrite, String>> {
        if !has_table_variables(profile) {
            return None;
        }
        let scale = x_scale(profile);
        Some(match slot(profile, &self.axis_order, number)? {
            Slot::Offset(n, field) => {
                let mut o = self.offset(n).copied().unwrap_or(Offset { number: n, ..Offset::default() });
                set(&mut o, field, value, scale).map(|()| TableWrite::Offset(o))
            }
            Slot::Work(system, letter) => {
                let mut p: Vec3 = self.work_mm[system];
                let i = usize::from(letter - b'X');
                p.set_axis(i, value / if i == 0 { scale } else { 1.0 });
                Ok(TableWrite::Work(system, p))
            }
        })
    }
}
