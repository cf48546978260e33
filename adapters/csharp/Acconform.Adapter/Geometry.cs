// Retail's names for where a thing is, as ACE and acdream name them; vectors are System.Numerics'.
using System.Numerics;

namespace Acconform.Adapter;

/// <summary>An origin (metres, within the landblock) and an orientation.</summary>
public sealed record Frame(Vector3 Origin, Quaternion Orientation);

/// <summary>A cell id (0xXXYYCCCC) and a frame in that cell's landblock.</summary>
public sealed record Position(uint ObjCellID, Frame Frame);
