using Fitfeel;
using UnityEngine;

/// <summary>
/// Steps fitfeel once per physics step with a tracked Transform (the haptic handle, a VR
/// controller) as the device, and keeps the wrench for whatever renders it (a device SDK, a
/// Rigidbody). Set Time.fixedDeltaTime to the scene's 1 / run.rate: fitfeel's tick is one
/// period of its own clock, whatever Unity's step is.
/// </summary>
public sealed class FitfeelStepper : MonoBehaviour
{
    [Tooltip("Scenario file, e.g. under StreamingAssets")]
    public string scenario = "paper-case1-h7js6.yaml";

    [Tooltip("The device: its position is the moving part's leading end, metres")]
    public Transform tool;

    [Tooltip("Optional: receives the force each step")]
    public Rigidbody body;

    /// <summary>The wrench of the last step, in Unity's frame.</summary>
    public Vector3 Force { get; private set; }
    public Vector3 Torque { get; private set; }

    Scene scene;
    DeviceState device;
    Vector3 lastPosition;
    float startTime;

    void Awake()
    {
        try
        {
            scene = Scene.OpenFile(System.IO.Path.Combine(Application.streamingAssetsPath, scenario));
        }
        catch (ScenarioException e)
        {
            // File, Line, Column and KeyPath point at the value to fix.
            Debug.LogError("fitfeel refused " + e.File + ":" + e.Line + ":" + e.Column + ": " + e.Message);
            enabled = false;
            return;
        }
        device.Orientation = Quaterniond.Identity;
        lastPosition = tool.position;
        startTime = Time.fixedTime;
    }

    void FixedUpdate()
    {
        Vector3 p = tool.position;
        Quaternion q = tool.rotation;
        float h = Time.fixedDeltaTime;
        // Unity is left-handed, fitfeel's scene frame right-handed: z is mirrored, which flips
        // the quaternion's x and y parts (a rotation about a mirrored axis turns the other way).
        device.Time = Time.fixedTime - startTime;
        device.Position = new Vector3d(p.x, p.y, -p.z);
        device.Orientation = new Quaterniond(q.w, -q.x, -q.y, q.z);
        device.Velocity = new Vector3d((p.x - lastPosition.x) / h, (p.y - lastPosition.y) / h,
                                       -(p.z - lastPosition.z) / h);
        lastPosition = p;
        Wrench w;
        if (!scene.Step(ref device, out w))
        {
            enabled = false;  // the scene's run.duration is used up
            return;
        }
        Force = new Vector3((float)w.Force.X, (float)w.Force.Y, -(float)w.Force.Z);
        Torque = new Vector3(-(float)w.Torque.X, -(float)w.Torque.Y, (float)w.Torque.Z);
        if (body != null) body.AddForce(Force);
    }

    void OnDestroy()
    {
        if (scene != null) scene.Dispose();
    }
}
