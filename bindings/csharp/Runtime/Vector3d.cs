using System.Runtime.InteropServices;

namespace Fitfeel
{
    /// <summary>
    /// Three doubles laid out as the C interface's double[3]; named apart from UnityEngine.Vector3
    /// (floats) so that both namespaces can be used in one file.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Vector3d
    {
        public double X, Y, Z;

        public Vector3d(double x, double y, double z)
        {
            X = x;
            Y = y;
            Z = z;
        }
    }
}
