//! Why a scene file could not be read: one error type for every reader of
//! scenes (JSON, NFF, and the OBJ meshes they name), each displayed as one
//! line naming the file and where in it.

/// Why a scene could not be loaded. Each displays as one line.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The file could not be read.
    #[error("cannot read {file}: {reason}")]
    Read {
        /// The file.
        file: String,
        /// The OS's reason.
        reason: String,
    },
    /// The text is not a scene: bad JSON, an unknown field, a wrong type.
    #[error("{file}:{line}:{column}: {message}")]
    Syntax {
        /// The file.
        file: String,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// The field path and what was expected.
        message: String,
    },
    /// A mesh's OBJ file cannot be used.
    #[error("{error} (the mesh of {file}: {field})")]
    Mesh {
        /// The scene file.
        file: String,
        /// The object's field, e.g. `objects[3].mesh.file`.
        field: String,
        /// What is wrong in the OBJ file, and where.
        error: crate::scene::obj::ObjError,
    },
    /// A value parses but is not allowed.
    #[error("{file}: {field}: {message}")]
    Invalid {
        /// The file.
        file: String,
        /// Path of the offending field, e.g. `objects[2].sphere.radius`.
        field: String,
        /// What is wrong.
        message: String,
    },
}
