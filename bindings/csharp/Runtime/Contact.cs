using System.Runtime.InteropServices;

namespace Fitfeel
{
    /// <summary>fitfeel_contact: the contact at the last step.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Contact
    {
        /// <summary>0 positioning (free motion), 1 constrained.</summary>
        public int Stage;
        /// <summary>Non-zero: the surfaces overlap along the axis.</summary>
        public int Engaged;
        /// <summary>Non-zero: some cell interferes.</summary>
        public int Interference;
        /// <summary>m, insertion depth.</summary>
        public double Depth;
        /// <summary>m.</summary>
        public double MaxInterference;
        /// <summary>m^3.</summary>
        public double InterferenceVolume;
        /// <summary>N, the model's force before the device's safety chain.</summary>
        public Vector3d ModelForce;
    }
}
