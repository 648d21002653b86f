using System.Runtime.InteropServices;

namespace Fitfeel
{
    /// <summary>fitfeel_wrench: what to render on the device, in the scene's frame.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Wrench
    {
        /// <summary>N.</summary>
        public Vector3d Force;
        /// <summary>N*m.</summary>
        public Vector3d Torque;
    }
}
