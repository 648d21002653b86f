using System.Runtime.InteropServices;

namespace Fitfeel
{
    /// <summary>A unit quaternion in the C interface's order w, x, y, z (Unity's is x, y, z, w).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Quaterniond
    {
        public double W, X, Y, Z;

        public Quaterniond(double w, double x, double y, double z)
        {
            W = w;
            X = x;
            Y = y;
            Z = z;
        }

        public static Quaterniond Identity
        {
            get { return new Quaterniond(1.0, 0.0, 0.0, 0.0); }
        }
    }
}
