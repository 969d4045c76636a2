//! Scenes: triangle meshes with materials, loaded from OBJ files or built in.
//!
//! A [`Mesh`] is what the host program draws: object-space positions and normals, and per triangle
//! three position indices, three normal indices and a material. Built-in scenes are deterministic
//! (no random numbers without a fixed seed) so that their images and counts can be compared run to run.

pub mod builtin;
pub mod obj;

/// A material in the Phong model of seed 001 eq. 4: ambient, diffuse and specular reflectances (0..1)
/// and the gloss n, a power of two 1..=16; and the opacity (MTL's dissolve `d`, or 1 - `Tr`), 0..=1
/// with 1 = opaque, which only PROOF uses (issue 22; the index-rendering chipset keeps one triangle per
/// pixel and refuses transparent materials).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Material {
    pub ambient: [f64; 3],
    pub diffuse: [f64; 3],
    pub specular: [f64; 3],
    pub gloss: u32,
    pub opacity: f64,
    /// The diffuse texture (MTL's `map_Kd`, resolved against the OBJ file's directory). The chipset
    /// holds one texture per frame: `render` textures every triangle with the first one a triangle
    /// names (docs/texture.md).
    pub texture: Option<std::path::PathBuf>,
}

impl Material {
    /// Opaque (the chipset's only case; PROOF blends the others).
    pub fn is_opaque(&self) -> bool {
        self.opacity >= 1.0
    }

    /// A plastic-like material of the given diffuse colour.
    pub fn plastic(diffuse: [f64; 3]) -> Material {
        Material { ambient: diffuse, diffuse, specular: [0.4, 0.4, 0.4], gloss: 16, opacity: 1.0, texture: None }
    }
}

/// One triangle of a mesh.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Triangle {
    /// Indices into [`Mesh::positions`].
    pub v: [u32; 3],
    /// Indices into [`Mesh::normals`] (per-corner normals, so creases can stay sharp).
    pub n: [u32; 3],
    /// Index into [`Mesh::materials`].
    pub material: u32,
}

/// Which winding the mesh's outside faces have, as seen from outside (OpenGL's glFrontFace).
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Winding {
    Ccw,
    Cw,
}

/// A triangle mesh in object space.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Mesh {
    pub name: String,
    pub positions: Vec<[f64; 3]>,
    pub normals: Vec<[f64; 3]>,
    pub materials: Vec<Material>,
    pub triangles: Vec<Triangle>,
    /// The winding of the outside faces: GLUT's teapot is `Cw`, OBJ files are `Ccw`.
    pub front_face: Winding,
    /// Texture coordinates (u, v): OBJ's `vt`. Empty when the mesh has none.
    pub texcoords: Vec<[f64; 2]>,
    /// Per triangle (parallel to `triangles`), its corners' indices into `texcoords`; empty when the
    /// mesh has no texture coordinates.
    pub triangle_texcoords: Vec<[u32; 3]>,
    /// The scene's own default view, if framing the whole mesh from the usual direction does not
    /// show it well (teapot-floor's long floor).
    pub view: Option<View>,
}

/// A default eye and point looked at (gluLookAt), in object space.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct View {
    pub eye: [f64; 3],
    pub center: [f64; 3],
}

impl Mesh {
    /// Centre and radius of a bounding sphere (centre of the axis-aligned box, radius to the farthest vertex).
    pub fn bounding_sphere(&self) -> ([f64; 3], f64) {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for p in &self.positions {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let c = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0, (lo[2] + hi[2]) / 2.0];
        let r = self
            .positions
            .iter()
            .map(|p| ((p[0] - c[0]).powi(2) + (p[1] - c[1]).powi(2) + (p[2] - c[2]).powi(2)).sqrt())
            .fold(0.0, f64::max);
        (c, r.max(1e-9))
    }

    /// Check the invariants the renderer relies on: indices in range, finite numbers, gloss a power of two.
    pub fn validate(&self) -> Result<(), String> {
        if self.triangles.is_empty() {
            return Err(format!("scene '{}' has no triangles", self.name));
        }
        for (i, p) in self.positions.iter().enumerate() {
            if p.iter().any(|c| !c.is_finite()) {
                return Err(format!("scene '{}': vertex {} has a non-finite coordinate {:?}", self.name, i + 1, p));
            }
        }
        for (i, n) in self.normals.iter().enumerate() {
            if n.iter().any(|c| !c.is_finite()) {
                return Err(format!("scene '{}': normal {} has a non-finite component {:?}", self.name, i + 1, n));
            }
        }
        for (i, t) in self.triangles.iter().enumerate() {
            if t.v.iter().any(|&v| v as usize >= self.positions.len())
                || t.n.iter().any(|&n| n as usize >= self.normals.len())
                || t.material as usize >= self.materials.len()
            {
                return Err(format!("scene '{}': triangle {} refers to a vertex, normal or material that does not exist", self.name, i + 1));
            }
        }
        if !self.triangle_texcoords.is_empty() && self.triangle_texcoords.len() != self.triangles.len() {
            return Err(format!("scene '{}': {} triangles but {} with texture coordinates", self.name, self.triangles.len(), self.triangle_texcoords.len()));
        }
        for (i, t) in self.triangle_texcoords.iter().enumerate() {
            if t.iter().any(|&k| k as usize >= self.texcoords.len()) {
                return Err(format!("scene '{}': triangle {} refers to a texture coordinate that does not exist", self.name, i + 1));
            }
        }
        for (i, c) in self.texcoords.iter().enumerate() {
            if c.iter().any(|x| !x.is_finite()) {
                return Err(format!("scene '{}': texture coordinate {} is not finite {:?}", self.name, i + 1, c));
            }
        }
        for m in &self.materials {
            if !(m.gloss.is_power_of_two() && m.gloss <= 16) {
                return Err(format!("scene '{}': gloss {} is not a power of two in 1..=16", self.name, m.gloss));
            }
            if !(0.0..=1.0).contains(&m.opacity) {
                return Err(format!("scene '{}': opacity {} is not in 0..=1 (1 = opaque)", self.name, m.opacity));
            }
        }
        Ok(())
    }
}
