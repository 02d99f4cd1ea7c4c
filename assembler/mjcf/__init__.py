"""The one layer that touches MuJoCo's model editing (MjSpec): load, prefix, attach, compile, emit."""
