using System.Text.Json;
using Acconform.Adapter;

public class Float32Tests
{
    static string Write(float x) => JsonSerializer.Serialize(x, Json.Options);

    static float Read(string json) => JsonSerializer.Deserialize<float>(json, Json.Options);

    [Theory]
    [InlineData(0x00000000u)]  // +0
    [InlineData(0x80000000u)]  // -0
    [InlineData(0x3dcccccdu)]  // 0.1
    [InlineData(0x7fc00000u)]  // the NaN .NET makes
    [InlineData(0x7fc00001u)]  // a NaN with a payload
    [InlineData(0xffc00000u)]  // a negative NaN
    [InlineData(0x7f800001u)]  // a signalling NaN
    [InlineData(0x7f800000u)]  // +inf
    [InlineData(0xff800000u)]  // -inf
    [InlineData(0x00000001u)]  // the smallest subnormal
    [InlineData(0x807fffffu)]  // the largest negative subnormal
    [InlineData(0x00800000u)]  // the smallest normal
    [InlineData(0x7f7fffffu)]  // float.MaxValue
    [InlineData(0xff7fffffu)]  // float.MinValue
    public void Every_float32_reads_back_to_its_own_bits(uint bits)
    {
        var x = BitConverter.UInt32BitsToSingle(bits);
        Assert.Equal(bits, BitConverter.SingleToUInt32Bits(Read(Write(x))));
    }

    [Theory]
    [InlineData(0x80000000u, "\"0x80000000\"")]
    [InlineData(0x7fc00001u, "\"0x7fc00001\"")]
    [InlineData(0xff800000u, "\"0xff800000\"")]
    [InlineData(0x3dcccccdu, "0.1")]
    [InlineData(0x00000000u, "0")]
    [InlineData(0x00000001u, "1E-45")]
    [InlineData(0x7f7fffffu, "3.4028235E+38")]
    public void Negative_zero_and_non_finite_floats_are_written_as_bit_patterns_the_rest_as_shortest_numbers(uint bits, string json) =>
        Assert.Equal(json, Write(BitConverter.UInt32BitsToSingle(bits)));

    [Theory]
    [InlineData("0.10000000149011612", 0x3dcccccdu)]  // the exact value, as JavaScript writes Math.fround(0.1)
    [InlineData("0.100000001", 0x3dcccccdu)]  // C's %.9g
    [InlineData("-0.0", 0x80000000u)]
    [InlineData("-0", 0x80000000u)]
    [InlineData("\"0x3DCCCCCD\"", 0x3dcccccdu)]
    public void A_float_is_read_from_any_decimal_naming_it_or_from_its_bit_pattern(string json, uint bits) =>
        Assert.Equal(bits, BitConverter.SingleToUInt32Bits(Read(json)));

    [Theory]
    [InlineData("\"0x3dcccc\"")]
    [InlineData("\"3dcccccd00\"")]
    [InlineData("\"0xzzzzzzzz\"")]
    public void A_bit_pattern_that_is_not_0x_and_8_hex_digits_is_refused(string json) =>
        Assert.Contains("8 hex digits", Assert.Throws<JsonException>(() => Read(json)).Message);

    [Fact]
    public void A_non_finite_double_is_written_as_its_16_digit_bit_pattern_and_read_back()
    {
        Assert.Equal("1000.05", JsonSerializer.Serialize(1000.05, Json.Options));
        var nan = BitConverter.UInt64BitsToDouble(0x7ff8000000000001);
        var json = JsonSerializer.Serialize(nan, Json.Options);
        Assert.Equal("\"0x7ff8000000000001\"", json);
        Assert.Equal(0x7ff8000000000001ul, BitConverter.DoubleToUInt64Bits(JsonSerializer.Deserialize<double>(json, Json.Options)));
    }
}
