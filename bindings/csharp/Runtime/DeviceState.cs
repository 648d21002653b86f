using System.Runtime.InteropServices;

namespace Fitfeel
{
    /// <summary>
    /// fitfeel_device_state: the device's state at a tick, in the scene's frame (y along the
    /// mating axis, 0 at the fixed part's entrance; right-handed), SI units. Blittable, so a step
    /// passes it without copying or allocating. The part's radial load is not here: the scene's
    /// part_motion gives it, as to `fitfeel run`.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct DeviceState
    {
        /// <summary>s since the start of the run.</summary>
        public double Time;
        /// <summary>m, the moving part's leading end.</summary>
        public Vector3d Position;
        public Quaterniond Orientation;
        /// <summary>m/s.</summary>
        public Vector3d Velocity;
        /// <summary>rad/s.</summary>
        public Vector3d AngularVelocity;
        public uint Buttons;
    }
}
