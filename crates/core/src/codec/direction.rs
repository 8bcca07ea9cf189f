//! Which way a frame travels: the one fact about a PDU that its length, its layout and its
//! reading all depend on, kept apart from the PDU types so that those can depend on them.

/// Which way a PDU travels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Direction {
    /// Master to slave.
    Request,
    /// Slave to master: a normal or an exception response.
    Response,
}

impl Direction {
    /// The other way.
    pub fn opposite(self) -> Direction {
        match self {
            Direction::Request => Direction::Response,
            Direction::Response => Direction::Request,
        }
    }
}
