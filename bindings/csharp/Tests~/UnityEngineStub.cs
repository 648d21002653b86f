// The few UnityEngine names the package's sample uses, with Unity's signatures, so that the
// sample compiles with mcs where Unity is not installed. Behaviour is not modelled: the test
// checks that the sample and the binding fit together, not what Unity does with them.
namespace UnityEngine
{
    public class Object
    {
    }

    public class Component : Object
    {
    }

    public class Behaviour : Component
    {
        public bool enabled { get; set; }
    }

    public class MonoBehaviour : Behaviour
    {
    }

    public class Transform : Component
    {
        public Vector3 position { get; set; }
        public Quaternion rotation { get; set; }
    }

    public class Rigidbody : Component
    {
        public void AddForce(Vector3 force)
        {
        }
    }

    public struct Vector3
    {
        public float x, y, z;

        public Vector3(float x, float y, float z)
        {
            this.x = x;
            this.y = y;
            this.z = z;
        }
    }

    public struct Quaternion
    {
        public float x, y, z, w;
    }

    public static class Time
    {
        public static float fixedTime { get { return 0f; } }
        public static float fixedDeltaTime { get { return 0.001f; } }
    }

    public static class Application
    {
        public static string streamingAssetsPath { get { return ""; } }
    }

    public static class Debug
    {
        public static void LogError(object message)
        {
        }
    }

    [System.AttributeUsage(System.AttributeTargets.Field)]
    public sealed class TooltipAttribute : System.Attribute
    {
        public TooltipAttribute(string tooltip)
        {
        }
    }
}
