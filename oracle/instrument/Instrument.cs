// acconform's instrumenter (MIT): writes a copy of the user's ACE.Entity.dll, ACE.DatLoader.dll and ACE.Server.dll in which
// every method the port anchors (port/anchors.py) calls a recorder at its entry and at each of its returns.
//
//     Instrument <ace dir> <out dir> <anchors file> <map file>
//
// <anchors file>: one anchor a line, as the port registers it ("Transition.cs:CliffSlide",
// "AFrame.cs:Rotate(Quaternion)", "ACE.DatLoader/Entity/Polygon.cs:Unpack"). Each is resolved to the ACE
// methods it names (module: ACE.DatLoader for an "ACE.DatLoader/..." anchor, ACE.Entity for an "ACE.Entity/..." one,
// else ACE.Server; type: the file's name, or for a partial class's file named Type_Part.cs (Player_Move.cs) the
// part before the underscore when no type has the whole name; method: the name, the constructors when it is the type's name, or the property getter; overloads: the
// parameter list when given -- or, when no method has that list, the overloads no other anchor claims whose list is
// the anchor's with trailing parameters added or dropped (a build before or after a fix that added one, as ACE's #2547
// gave add_all_outside_cells its `uint id`) -- else every overload no anchor with a parameter list claims). <map file> gets one
// line per instrumented method: "id<TAB>anchor<TAB>Type::Method(params)<TAB>flags" (flags: s static, c
// constructor), then "unresolved<TAB>anchor" for each anchor that names no method of this build.
//
// The hooks: a type Acconform.Trace.Hooks injected into ACE.Entity (ACE.DatLoader and ACE.Server reference it), with
//     public static Hooks Current;
//     public abstract void Enter(int id, object[] args);              // this (null in a constructor), the parameters
//     public abstract void Exit(int id, object result, object[] refs); // the answer (a constructor's: this); with ref or
//         out parameters, refs: their values, after the answer when the method has one
// An instrumented method does nothing more while Current is null: a test of a static field at its entry and exit.
// Every type's static initializer (.cctor) in the three assemblies runs with Current null (`Quiet`): it runs once a
// process, and its records would land in whichever trace happened to come first.
// Nothing of ACE is written anywhere but <out dir>, the user's cache.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Mono.Cecil;
using Mono.Cecil.Cil;
using Mono.Cecil.Rocks;

static class Instrument
{
    const string HooksNamespace = "Acconform.Trace";

    static int Main(string[] argv)
    {
        if (argv.Length != 4)
        {
            Console.Error.WriteLine("usage: Instrument <ace dir> <out dir> <anchors file> <map file>");
            return 2;
        }
        var aceDir = argv[0];
        var outDir = argv[1];
        var anchors = File.ReadAllLines(argv[2]).Where(l => l.Trim().Length > 0).ToList();
        var resolver = new DefaultAssemblyResolver();
        resolver.AddSearchDirectory(aceDir);
        var rp = new ReaderParameters { AssemblyResolver = resolver, ReadSymbols = false, InMemory = true };
        var entity = AssemblyDefinition.ReadAssembly(Path.Combine(aceDir, "ACE.Entity.dll"), rp);
        var dat = AssemblyDefinition.ReadAssembly(Path.Combine(aceDir, "ACE.DatLoader.dll"), rp);
        var server = AssemblyDefinition.ReadAssembly(Path.Combine(aceDir, "ACE.Server.dll"), rp);

        var hooks = InjectHooks(entity.MainModule);
        var map = new List<string>();
        var id = 0;
        var claimed = new HashSet<MethodDefinition>();
        // anchors with a parameter list first, exactly; then those whose list no method has, by its trailing parameters
        // added or dropped; an anchor without one takes the overloads left
        var pending = new HashSet<string>(anchors);
        foreach (var pass in new[] { 0, 1, 2 })
        foreach (var anchor in anchors.Where(a => pending.Contains(a) && (a.Contains("(") ? pass < 2 : pass == 2)))
        {
            var module = anchor.StartsWith("ACE.DatLoader/") ? dat.MainModule
                       : anchor.StartsWith("ACE.Entity/") ? entity.MainModule : server.MainModule;
            var methods = Resolve(module, anchor, pass == 1).Where(m => m.HasBody && !claimed.Contains(m)).ToList();
            if (methods.Count == 0 && pass == 0) continue;  // tried again by its trailing parameters
            pending.Remove(anchor);
            if (methods.Count == 0)
            {
                map.Add("unresolved\t" + anchor);
                continue;
            }
            foreach (var m in methods)
            {
                claimed.Add(m);
                Rewrite(m, id, hooks);
                map.Add(id + "\t" + anchor + "\t" + m.DeclaringType.FullName + "::" + m.Name + "(" +
                        string.Join(", ", m.Parameters.Select(p => Short(p.ParameterType))) + ")\t" +
                        (m.IsStatic ? "s" : "") + (m.IsConstructor ? "c" : ""));
                id++;
            }
        }
        foreach (var module in new[] { entity.MainModule, dat.MainModule, server.MainModule })
            foreach (var t in AllTypes(module).ToList())
            {
                var cctor = t.Methods.FirstOrDefault(x => x.IsConstructor && x.IsStatic && x.HasBody);
                if (cctor != null) Quiet(cctor, hooks);
            }
        Directory.CreateDirectory(outDir);
        entity.Write(Path.Combine(outDir, "ACE.Entity.dll"));
        dat.Write(Path.Combine(outDir, "ACE.DatLoader.dll"));
        server.Write(Path.Combine(outDir, "ACE.Server.dll"));
        File.WriteAllLines(argv[3], map);
        return 0;
    }

    sealed class HookRefs { public FieldReference Current; public MethodReference Enter, Exit; public TypeReference Type; }

    static HookRefs InjectHooks(ModuleDefinition module)
    {
        var ts = module.TypeSystem;
        var type = new TypeDefinition(HooksNamespace, "Hooks",
            TypeAttributes.Public | TypeAttributes.Abstract | TypeAttributes.Class | TypeAttributes.BeforeFieldInit, ts.Object);
        var current = new FieldDefinition("Current", FieldAttributes.Public | FieldAttributes.Static, type);
        type.Fields.Add(current);
        var objArray = new ArrayType(ts.Object);
        var enter = new MethodDefinition("Enter", MethodAttributes.Public | MethodAttributes.Abstract | MethodAttributes.Virtual |
                                                  MethodAttributes.NewSlot | MethodAttributes.HideBySig, ts.Void);
        enter.Parameters.Add(new ParameterDefinition("id", ParameterAttributes.None, ts.Int32));
        enter.Parameters.Add(new ParameterDefinition("args", ParameterAttributes.None, objArray));
        var exit = new MethodDefinition("Exit", enter.Attributes, ts.Void);
        exit.Parameters.Add(new ParameterDefinition("id", ParameterAttributes.None, ts.Int32));
        exit.Parameters.Add(new ParameterDefinition("result", ParameterAttributes.None, ts.Object));
        exit.Parameters.Add(new ParameterDefinition("refs", ParameterAttributes.None, objArray));
        type.Methods.Add(enter);
        type.Methods.Add(exit);
        var ctor = new MethodDefinition(".ctor", MethodAttributes.Family | MethodAttributes.HideBySig | MethodAttributes.SpecialName |
                                                 MethodAttributes.RTSpecialName, ts.Void);
        var objCtor = new MethodReference(".ctor", ts.Void, ts.Object) { HasThis = true };
        var il = ctor.Body.GetILProcessor();
        il.Emit(OpCodes.Ldarg_0);
        il.Emit(OpCodes.Call, module.ImportReference(objCtor));
        il.Emit(OpCodes.Ret);
        type.Methods.Add(ctor);
        module.Types.Add(type);
        return new HookRefs { Current = current, Enter = enter, Exit = exit, Type = type };
    }

    // ------------------------------------------------------------------ resolving an anchor
    static IEnumerable<MethodDefinition> Resolve(ModuleDefinition module, string anchor, bool byPrefix = false)
    {
        var colon = anchor.LastIndexOf(".cs:", StringComparison.Ordinal);
        var file = anchor.Substring(0, colon);
        var member = anchor.Substring(colon + 4);
        var slash = file.LastIndexOf('/');
        var typeName = file.Substring(slash + 1);
        string fileClass;
        var className = FileClasses.TryGetValue(typeName, out fileClass) ? fileClass : typeName;
        string ns = null;  // an exact namespace for "ACE.X/Dir/File.cs", else ACE.Server.Physics.*
        if (slash >= 0) ns = file.Substring(0, slash).Replace('/', '.');
        string method = member;
        List<string> pars = null;
        var paren = member.IndexOf('(');
        if (paren >= 0)
        {
            method = member.Substring(0, paren);
            pars = SplitParams(member.Substring(paren + 1, member.Length - paren - 2));
        }
        var dot = method.LastIndexOf('.');
        if (dot >= 0)  // "Class.Method": a class of the file not named after it (MovementParamFlags.cs' helper)
        {
            className = method.Substring(0, dot);
            method = method.Substring(dot + 1);
        }
        Func<TypeDefinition, bool> inFile = t => ns != null ? t.Namespace == ns
                                                     : t.Namespace.StartsWith("ACE.Server.Physics", StringComparison.Ordinal);
        var underscore = className.IndexOf('_');
        if (underscore > 0 && !AllTypes(module).Any(t => t.Name == className && inFile(t)))
            className = className.Substring(0, underscore);  // Player_Move.cs: a part of the partial class Player
        foreach (var t in AllTypes(module))
        {
            if (t.Name != className) continue;
            if (!inFile(t)) continue;
            foreach (var m in t.Methods)
            {
                var named = method == className ? m.IsConstructor && !m.IsStatic
                                               : m.Name == method || m.Name == "get_" + method;
                if (!named) continue;
                if (pars != null && !(byPrefix ? ParamsPrefix(m, pars) : ParamsMatch(m, pars))) continue;
                yield return m;
            }
        }
    }

    // files whose class is not named after them
    static readonly Dictionary<string, string> FileClasses = new Dictionary<string, string> { { "Vector", "Vec" } };

    static IEnumerable<TypeDefinition> AllTypes(ModuleDefinition module)
    {
        var stack = new Stack<TypeDefinition>(module.Types);
        while (stack.Count > 0)
        {
            var t = stack.Pop();
            yield return t;
            foreach (var n in t.NestedTypes) stack.Push(n);
        }
    }

    static List<string> SplitParams(string text)
    {
        var parts = new List<string>();
        var depth = 0;
        var start = 0;
        for (var i = 0; i < text.Length; i++)
        {
            if (text[i] == '<') depth++;
            else if (text[i] == '>') depth--;
            else if (text[i] == ',' && depth == 0) { parts.Add(text.Substring(start, i - start)); start = i + 1; }
        }
        if (text.Trim().Length > 0) parts.Add(text.Substring(start));
        return parts.Select(NormalizeText).ToList();
    }

    static string NormalizeText(string p)
    {
        p = p.Trim();
        foreach (var word in new[] { "ref ", "out ", "in ", "params ", "this " })
            if (p.StartsWith(word, StringComparison.Ordinal)) p = p.Substring(word.Length).Trim();
        var sp = p.IndexOf(' ');
        if (sp > 0 && p.IndexOf('<') < 0) p = p.Substring(0, sp);  // "Vector3 offset": the type
        if (p.EndsWith("?", StringComparison.Ordinal)) p = "Nullable<" + p.Substring(0, p.Length - 1) + ">";  // C#'s T?
        var lt = p.IndexOf('<');
        var head = lt >= 0 ? p.Substring(0, lt) : p;
        head = head.Substring(head.LastIndexOf('.') + 1);
        if (lt < 0) return head;
        var inner = p.Substring(lt + 1, p.LastIndexOf('>') - lt - 1);
        return head + "<" + string.Join(",", SplitParams(inner)) + ">";
    }

    static readonly Dictionary<string, string> Aliases = new Dictionary<string, string>
    {
        { "Int32", "int" }, { "UInt32", "uint" }, { "Int16", "short" }, { "UInt16", "ushort" }, { "Byte", "byte" },
        { "SByte", "sbyte" }, { "Int64", "long" }, { "UInt64", "ulong" }, { "Single", "float" }, { "Double", "double" },
        { "Boolean", "bool" }, { "String", "string" }, { "Object", "object" }, { "Void", "void" },
    };

    static string Short(TypeReference t)
    {
        if (t is ByReferenceType br) return Short(br.ElementType);
        if (t is ArrayType at) return Short(at.ElementType) + "[]";
        if (t is GenericInstanceType g)
        {
            var head = g.ElementType.Name;
            head = head.Substring(0, head.IndexOf('`') < 0 ? head.Length : head.IndexOf('`'));
            return head + "<" + string.Join(",", g.GenericArguments.Select(Short)) + ">";
        }
        var name = t.Name;
        if (name.IndexOf('`') >= 0) name = name.Substring(0, name.IndexOf('`'));
        return Aliases.TryGetValue(name, out var a) ? a : name;
    }

    static bool ParamsMatch(MethodDefinition m, List<string> pars)
    {
        var have = m.Parameters.Select(p => Short(p.ParameterType)).ToList();
        if (have.SequenceEqual(pars)) return true;
        // an extension method's anchor leaves out the reader it reads from (UnpackableExtensions: "Unpack(List<T>)"
        // for Unpack<T>(this List<T> value, BinaryReader reader))
        var extension = m.IsStatic && m.CustomAttributes.Any(a => a.AttributeType.Name == "ExtensionAttribute");
        return extension && have.Where(h => h != "BinaryReader").SequenceEqual(pars);
    }

    /// <summary>Whether m's parameter list and the anchor's differ only by trailing parameters, one a prefix of the other.</summary>
    static bool ParamsPrefix(MethodDefinition m, List<string> pars)
    {
        var have = m.Parameters.Select(p => Short(p.ParameterType)).ToList();
        var n = Math.Min(have.Count, pars.Count);
        return n > 0 && have.Count != pars.Count && have.Take(n).SequenceEqual(pars.Take(n));
    }

    // ------------------------------------------------------------------ rewriting a method
    static void Rewrite(MethodDefinition m, int id, HookRefs hooks)
    {
        var module = m.Module;
        var ts = module.TypeSystem;
        var current = module.ImportReference(hooks.Current);
        var enter = module.ImportReference(hooks.Enter);
        var exit = module.ImportReference(hooks.Exit);
        var body = m.Body;
        body.SimplifyMacros();
        var il = body.GetILProcessor();
        var first = body.Instructions[0];

        // entry: if (Hooks.Current != null) Hooks.Current.Enter(id, new object[] { this, args... })
        var entry = new List<Instruction>();
        entry.Add(il.Create(OpCodes.Ldsfld, current));
        entry.Add(il.Create(OpCodes.Brfalse, first));
        entry.Add(il.Create(OpCodes.Ldsfld, current));
        entry.Add(il.Create(OpCodes.Ldc_I4, id));
        var slots = new List<Action<List<Instruction>>>();
        if (m.HasThis)
        {
            if (m.IsConstructor) slots.Add(l => l.Add(il.Create(OpCodes.Ldnull)));  // `this` is not built yet
            else slots.Add(l => { l.Add(il.Create(OpCodes.Ldarg_0)); if (m.DeclaringType.IsValueType) l.Add(il.Create(OpCodes.Ldobj, m.DeclaringType)); BoxIfValue(il, l, m.DeclaringType); });
        }
        foreach (var p in m.Parameters)
        {
            var param = p;
            if (param.IsOut) slots.Add(l => l.Add(il.Create(OpCodes.Ldnull)));  // not written yet
            else slots.Add(l => LoadParam(il, l, param));
        }
        entry.Add(il.Create(OpCodes.Ldc_I4, slots.Count));
        entry.Add(il.Create(OpCodes.Newarr, ts.Object));
        for (var i = 0; i < slots.Count; i++)
        {
            entry.Add(il.Create(OpCodes.Dup));
            entry.Add(il.Create(OpCodes.Ldc_I4, i));
            slots[i](entry);
            entry.Add(il.Create(OpCodes.Stelem_Ref));
        }
        entry.Add(il.Create(OpCodes.Callvirt, enter));
        foreach (var ins in entry) il.InsertBefore(first, ins);

        // exits: every `ret` stores the answer and goes to one epilogue that reports it, then returns it
        var isVoid = m.ReturnType.MetadataType == MetadataType.Void;
        VariableDefinition result = null;
        if (!isVoid)
        {
            result = new VariableDefinition(m.ReturnType);
            body.Variables.Add(result);
            body.InitLocals = true;
        }
        var rets = body.Instructions.Where(i => i.OpCode == OpCodes.Ret).ToList();
        var epilogue = il.Create(OpCodes.Nop);
        foreach (var ret in rets)
        {
            if (isVoid)
            {
                ret.OpCode = OpCodes.Br;
                ret.Operand = epilogue;
            }
            else
            {
                ret.OpCode = OpCodes.Stloc;
                ret.Operand = result;
                il.InsertAfter(ret, il.Create(OpCodes.Br, epilogue));
            }
        }
        var final = isVoid ? il.Create(OpCodes.Ret) : il.Create(OpCodes.Ldloc, result);
        var tail = new List<Instruction> { epilogue, il.Create(OpCodes.Ldsfld, current), il.Create(OpCodes.Brfalse, final),
                                           il.Create(OpCodes.Ldsfld, current), il.Create(OpCodes.Ldc_I4, id) };
        if (m.IsConstructor) tail.Add(il.Create(OpCodes.Ldarg_0));
        else if (isVoid) tail.Add(il.Create(OpCodes.Ldnull));
        else
        {
            tail.Add(il.Create(OpCodes.Ldloc, result));
            BoxIfValue(il, tail, m.ReturnType);
        }
        var refs = m.Parameters.Where(p => p.ParameterType.IsByReference).ToList();
        // with ref or out parameters, the answer as the port's routines give it: a void method's ref values, or the
        // answer followed by them
        if (refs.Count == 0 || m.IsConstructor) tail.Add(il.Create(OpCodes.Ldnull));
        else
        {
            var lead = isVoid ? 0 : 1;
            tail.Add(il.Create(OpCodes.Ldc_I4, refs.Count + lead));
            tail.Add(il.Create(OpCodes.Newarr, ts.Object));
            if (!isVoid)
            {
                tail.Add(il.Create(OpCodes.Dup));
                tail.Add(il.Create(OpCodes.Ldc_I4, 0));
                tail.Add(il.Create(OpCodes.Ldloc, result));
                BoxIfValue(il, tail, m.ReturnType);
                tail.Add(il.Create(OpCodes.Stelem_Ref));
            }
            for (var i = 0; i < refs.Count; i++)
            {
                tail.Add(il.Create(OpCodes.Dup));
                tail.Add(il.Create(OpCodes.Ldc_I4, i + lead));
                LoadParam(il, tail, refs[i]);
                tail.Add(il.Create(OpCodes.Stelem_Ref));
            }
        }
        tail.Add(il.Create(OpCodes.Callvirt, exit));
        tail.Add(final);
        if (!isVoid) tail.Add(il.Create(OpCodes.Ret));
        foreach (var ins in tail) il.Append(ins);
        body.OptimizeMacros();
    }

    // A type's static initializer runs once a process, where the runtime first needs it: its records (ObjCell.EmptyCell's
    // `new ObjCell()`, PhysicsGlobals.DummySphere's Sphere) would land in whichever trace came first, wherever its JIT ran
    // it. It runs with the recorder off: { var saved = Hooks.Current; Hooks.Current = null; ...; Hooks.Current = saved; }
    static void Quiet(MethodDefinition cctor, HookRefs hooks)
    {
        var current = cctor.Module.ImportReference(hooks.Current);
        var body = cctor.Body;
        body.SimplifyMacros();
        var il = body.GetILProcessor();
        var saved = new VariableDefinition(current.FieldType);
        body.Variables.Add(saved);
        body.InitLocals = true;
        var first = body.Instructions[0];
        il.InsertBefore(first, il.Create(OpCodes.Ldsfld, current));
        il.InsertBefore(first, il.Create(OpCodes.Stloc, saved));
        il.InsertBefore(first, il.Create(OpCodes.Ldnull));
        il.InsertBefore(first, il.Create(OpCodes.Stsfld, current));
        var epilogue = il.Create(OpCodes.Ldloc, saved);
        foreach (var ret in body.Instructions.Where(i => i.OpCode == OpCodes.Ret).ToList())
        {
            ret.OpCode = OpCodes.Br;
            ret.Operand = epilogue;
        }
        il.Append(epilogue);
        il.Append(il.Create(OpCodes.Stsfld, current));
        il.Append(il.Create(OpCodes.Ret));
        body.OptimizeMacros();
    }

    static void LoadParam(ILProcessor il, List<Instruction> l, ParameterDefinition p)
    {
        var t = p.ParameterType;
        l.Add(il.Create(OpCodes.Ldarg, p));
        if (t is ByReferenceType br)
        {
            t = br.ElementType;
            l.Add(il.Create(OpCodes.Ldobj, t));
        }
        BoxIfValue(il, l, t);
    }

    static void BoxIfValue(ILProcessor il, List<Instruction> l, TypeReference t)
    {
        // a signature says whether a type is a value type (valuetype / class); a generic parameter may be one
        if (t.IsValueType || t.IsPrimitive || t.IsGenericParameter)
            l.Add(il.Create(OpCodes.Box, t));
    }
}
